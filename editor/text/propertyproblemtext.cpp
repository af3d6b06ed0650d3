#include "editor/text/propertyproblemtext.h"

#include "editor/text/conditionerrortext.h"
#include "editor/text/conditiontypeerrortext.h"
#include "editor/text/displaytext.h"

#include "core/verification/property.h"

#include <QCoreApplication>

namespace editor {

namespace {

class PropertyProblemText {
    Q_DECLARE_TR_FUNCTIONS(PropertyProblemText)

public:
    static QString text(const core::PropertyProblem& problem)
    {
        namespace code = core::property;
        // The user's words, quoted: a name of 50,000 letters would widen the panel.
        const auto argument = [&](std::size_t i) {
            return i < problem.arguments.size() ? elidedText(QString::fromStdString(problem.arguments[i])) : QString();
        };
        if (problem.syntax)
            return conditionErrorText(*problem.syntax);
        if (problem.type)
            return conditionTypeErrorText(*problem.type);
        if (problem.code == code::kUnknownVariable)
            return tr("'%1' is not a declared variable").arg(argument(0));
        if (problem.code == code::kUnknownStep)
            return tr("there is no visible GEMMA step '%1'").arg(argument(0));
        if (problem.code == code::kNoGrafcet)
            return tr("the step %1 has no nested GRAFCET").arg(argument(0));
        if (problem.code == code::kUnknownNestedStep)
            return tr("the GRAFCET of %1 has no step %2").arg(argument(0), argument(1));
        if (problem.code == code::kFaultedWithoutFaults)
            return tr("'%1' is only defined when verifying with single faults (Simulation > Verify with Single "
                      "Faults, with the machine)")
                .arg(argument(0));
        return QString::fromStdString(problem.message);
    }
};

} // namespace

QString propertyProblemText(const core::PropertyProblem& problem)
{
    return PropertyProblemText::text(problem);
}

} // namespace editor
