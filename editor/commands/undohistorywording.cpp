#include "editor/commands/undohistorywording.h"

#include "editor/commands/modelcommand.h"

#include <QObject>
#include <QUndoStack>

#include <algorithm>
#include <utility>
#include <vector>

namespace editor {

namespace {

// The macros of one stack and their wordings; a child of the stack. The
// macros are only looked at while they are still in the stack: an entry
// whose macro the stack deleted is forgotten at the stack's next change,
// before its address could be given to a new macro.
class MacroWordings : public QObject {
public:
    explicit MacroWordings(QUndoStack* stack)
        : QObject(stack)
        , m_stack(stack)
    {
        setObjectName(QStringLiteral("macroWordings"));
        connect(stack, &QUndoStack::indexChanged, this, &MacroWordings::forgetDeleted);
        connect(stack, &QUndoStack::cleanChanged, this, &MacroWordings::forgetDeleted);
    }

    static MacroWordings* of(QUndoStack* stack)
    {
        auto* wordings = dynamic_cast<MacroWordings*>(
            stack->findChild<QObject*>(QStringLiteral("macroWordings"), Qt::FindDirectChildrenOnly));
        return wordings ? wordings : new MacroWordings(stack);
    }

    void add(const QUndoCommand* macro, std::function<QString()> wording)
    {
        m_wordings.emplace_back(macro, std::move(wording));
    }

    // The wording of the stack's entry, when it is a worded macro.
    const std::function<QString()>* wordingOf(const QUndoCommand* command) const
    {
        for (const auto& [macro, wording] : m_wordings) {
            if (macro == command)
                return &wording;
        }
        return nullptr;
    }

    void forgetDeleted()
    {
        std::vector<const QUndoCommand*> present;
        for (int i = 0; i < m_stack->count(); ++i)
            present.push_back(m_stack->command(i));
        std::erase_if(m_wordings, [&present](const auto& entry) {
            return std::find(present.begin(), present.end(), entry.first) == present.end();
        });
    }

private:
    QUndoStack* m_stack;
    std::vector<std::pair<const QUndoCommand*, std::function<QString()>>> m_wordings;
};

} // namespace

void beginWordedMacro(QUndoStack* stack, std::function<QString()> wording)
{
    MacroWordings* wordings = MacroWordings::of(stack);
    wordings->forgetDeleted();
    const auto lastEntry = [stack]() -> const QUndoCommand* {
        return stack->count() > 0 ? stack->command(stack->count() - 1) : nullptr;
    };
    const QUndoCommand* lastBefore = lastEntry();
    stack->beginMacro(wording());
    // A macro begun inside another is that one's child, not a new entry of the stack.
    if (const QUndoCommand* macro = lastEntry(); macro && macro != lastBefore)
        wordings->add(macro, std::move(wording));
}

void rewordUndoHistory(QUndoStack* stack)
{
    MacroWordings* wordings = MacroWordings::of(stack);
    wordings->forgetDeleted();
    for (int i = 0; i < stack->count(); ++i) {
        // The stack hands out its entries as const; they are its own, not const objects.
        auto* command = const_cast<QUndoCommand*>(stack->command(i));
        if (auto* modelCommand = dynamic_cast<ModelCommand*>(command))
            modelCommand->reword();
        else if (const std::function<QString()>* wording = wordings->wordingOf(command))
            command->setText((*wording)());
    }
}

} // namespace editor
