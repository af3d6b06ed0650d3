#pragma once

// What the tests of the PackML panels share: the model's PackML
// configuration, a named child, whether a condition's problems mention a text.

#include "editor/docks/conditionedit.h"
#include "editor/document.h"

#include "core/model/model.h"

#include <QLatin1String>
#include <QList>
#include <QObject>
#include <QString>
#include <QtGlobal>

namespace packmldocktest {

inline const core::packml::Configuration& config(const editor::Document& document)
{
    return *document.model().packml();
}

// The child of `parent` with that object name; warns when there is none,
// so that a failing test says which it looked for.
template <typename T>
T* child(const QObject& parent, const QString& name)
{
    T* found = parent.findChild<T*>(name);
    if (!found)
        qWarning("no child %s", qPrintable(name));
    return found;
}

inline bool mentions(const QList<editor::ConditionEdit::Problem>& problems, const char* text)
{
    for (const editor::ConditionEdit::Problem& problem : problems)
        if (problem.message.contains(QLatin1String(text)))
            return true;
    return false;
}

} // namespace packmldocktest
