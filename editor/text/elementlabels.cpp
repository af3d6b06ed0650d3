#include "editor/text/elementlabels.h"

#include "core/model/model.h"

#include <QCoreApplication>

namespace editor {

namespace {

class ElementLabels {
    Q_DECLARE_TR_FUNCTIONS(ElementLabels)
};

QString sourceLabel(const QString& source)
{
    return source == QLatin1String(core::kFamilySource.data(), static_cast<qsizetype>(core::kFamilySource.size()))
        ? ElementLabels::tr("F (family)")
        : source;
}

} // namespace

QString transitionLabel(const core::Transition& transition)
{
    return transitionLabel(QString::fromStdString(transition.id));
}

QString transitionLabel(const QString& transitionId)
{
    const int arrow = transitionId.indexOf(QLatin1String("->"));
    if (arrow < 0)
        return transitionId;
    //: a transition: source step, arrow, target step
    return ElementLabels::tr("%1 → %2").arg(sourceLabel(transitionId.left(arrow)), transitionId.mid(arrow + 2));
}

QString stepTypeText(core::StepType type)
{
    switch (type) {
    case core::StepType::Simple:
        return ElementLabels::tr("Simple step");
    case core::StepType::Macro:
        return ElementLabels::tr("Macro-step");
    case core::StepType::Enclosing:
        return ElementLabels::tr("Enclosing step");
    }
    return {};
}

QString ineffectiveReason(const core::Model& model, const core::Transition& transition)
{
    if (model.isEffective(transition))
        return {};
    if (transition.hidden)
        return ElementLabels::tr("hidden");
    const core::Step* source = model.step(transition.source);
    if (source && source->hidden)
        return ElementLabels::tr("source %1 hidden").arg(QString::fromStdString(source->id));
    return ElementLabels::tr("target %1 hidden").arg(QString::fromStdString(transition.target));
}

} // namespace editor
