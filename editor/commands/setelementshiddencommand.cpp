#include "editor/commands/setelementshiddencommand.h"

#include "editor/commands/initialsteprule.h"

#include "core/model/model.h"

namespace editor {

namespace {

QString commandText(const QList<ElementRef>& elements, bool hidden)
{
    const int count = int(elements.size());
    return hidden ? SetElementsHiddenCommand::tr("Hide %n element(s)", nullptr, count)
                  : SetElementsHiddenCommand::tr("Show %n element(s)", nullptr, count);
}

} // namespace

SetElementsHiddenCommand::SetElementsHiddenCommand(Document& document, const QList<ElementRef>& elements, bool hidden)
    : ModelCommand(document, [=] { return commandText(elements, hidden); })
    , m_elements(elements)
    , m_hidden(hidden)
{
}

core::Status SetElementsHiddenCommand::setHidden(const ElementRef& element, bool hidden)
{
    const std::string id = toStdString(element.id);
    if (element.kind == ElementRef::Kind::Step)
        return model().setStepHidden(id, hidden);
    if (element.kind == ElementRef::Kind::Transition)
        return model().setTransitionHidden(id, hidden);
    return core::Status::failure("not-hideable", "only steps and transitions can be hidden");
}

core::Status SetElementsHiddenCommand::apply()
{
    if (firstRun() && m_hidden) {
        // All or nothing: hiding the others alone would not be what was asked.
        if (const QString refusal = InitialStepRule::hidingRefusal(model(), m_elements); !refusal.isEmpty())
            return core::Status::failure("initial-step-hidden", toStdString(refusal));
    }
    if (firstRun()) {
        for (const ElementRef& element : m_elements) {
            const std::string id = toStdString(element.id);
            const core::Step* step = element.kind == ElementRef::Kind::Step ? model().step(id) : nullptr;
            const core::Transition* transition =
                element.kind == ElementRef::Kind::Transition ? model().transition(id) : nullptr;
            const bool already = (step && step->hidden == m_hidden) || (transition && transition->hidden == m_hidden);
            if ((step || transition) && !already)
                m_changed << element;
        }
    }
    for (const ElementRef& element : m_changed) {
        if (core::Status status = setHidden(element, m_hidden); !status)
            return status;
    }
    return core::Status::success();
}

core::Status SetElementsHiddenCommand::revert()
{
    for (auto it = m_changed.crbegin(); it != m_changed.crend(); ++it) {
        if (core::Status status = setHidden(*it, !m_hidden); !status)
            return status;
    }
    return core::Status::success();
}

} // namespace editor
