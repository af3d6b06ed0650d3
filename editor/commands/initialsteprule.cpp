#include "editor/commands/initialsteprule.h"

#include "core/model/model.h"

namespace editor {

QString InitialStepRule::hidingRefusal(const core::Model& model, const QList<ElementRef>& elements)
{
    for (const ElementRef& element : elements) {
        if (element.kind != ElementRef::Kind::Step)
            continue;
        if (QString refusal = hidingRefusal(model, element.id); !refusal.isEmpty())
            return refusal;
    }
    return {};
}

QString InitialStepRule::hidingRefusal(const core::Model& model, const QString& stepId)
{
    const core::Step* step = model.step(stepId.toStdString());
    if (!step || !step->initial || step->hidden)
        return {};
    //: %1 is a GEMMA step, e.g. A1
    return tr("%1 is the initial step, which cannot be hidden; make another step initial first").arg(stepId);
}

QString InitialStepRule::initialRefusal(const core::Model& model, const QString& stepId)
{
    const core::Step* step = model.step(stepId.toStdString());
    if (!step || step->initial || !step->hidden)
        return {};
    //: %1 is a GEMMA step, e.g. A3
    return tr("%1 is hidden and cannot be the initial step; show it first").arg(stepId);
}

} // namespace editor
