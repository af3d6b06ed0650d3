#pragma once

#include "editor/elementref.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace core {
class Model;
}

namespace editor {

// The initial step is never hidden: the PLC starts in it, and a hidden step
// has no code, so the simulation and the PLC would start nowhere. Every
// editing path asks here before hiding a step or making one initial, and is
// refused with the reason. A file that hides its initial step still opens as
// it is (the checks report GG001), so that showing the step or making
// another one initial repairs it.
class InitialStepRule {
    Q_DECLARE_TR_FUNCTIONS(InitialStepRule)

public:
    // Why the elements cannot be hidden; empty when they can.
    static QString hidingRefusal(const core::Model& model, const QList<ElementRef>& elements);
    static QString hidingRefusal(const core::Model& model, const QString& stepId);
    // Why `stepId` cannot become the initial step; empty when it can.
    static QString initialRefusal(const core::Model& model, const QString& stepId);
};

} // namespace editor
