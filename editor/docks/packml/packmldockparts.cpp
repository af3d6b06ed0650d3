#include "editor/docks/packml/packmldockparts.h"

#include "editor/docks/wrappinglabel.h"
#include "editor/stdstring.h"
#include "editor/style/secondarytext.h"
#include "editor/text/diagnostictext.h"

#include "core/model/model.h"

namespace editor {

QList<ConditionEdit::Problem> conditionProblems(const QString& condition,
                                                const std::vector<core::Diagnostic>& diagnostics)
{
    QList<ConditionEdit::Problem> problems;
    for (const core::Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.field != "condition" || !diagnostic.span)
            continue;
        ConditionEdit::Problem problem;
        problem.begin = ConditionEdit::positionOfByte(condition, diagnostic.span->begin);
        problem.end = ConditionEdit::positionOfByte(condition, diagnostic.span->end);
        problem.message = diagnosticText(diagnostic);
        problem.error = diagnostic.severity == core::Severity::Error;
        problems << problem;
    }
    return problems;
}

QLabel* packmlHintLabel(QWidget* parent)
{
    auto* label = new WrappingLabel(parent);
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    label->setFont(font);
    useSecondaryText(label);
    return label;
}

QStringList declaredVariableNames(const core::Model& model)
{
    QStringList names;
    for (const core::Variable& variable : model.variables())
        names << fromStd(variable.name);
    return names;
}

} // namespace editor
