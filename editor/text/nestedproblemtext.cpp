#include "editor/text/nestedproblemtext.h"

#include "editor/stdstring.h"
#include "editor/text/conditionerrortext.h"
#include "editor/text/conditiontypeerrortext.h"
#include "editor/text/diagnostictext.h"

#include "core/condition/conditionparseerror.h"
#include "core/condition/conditiontypeerror.h"

#include <QCoreApplication>

#include <optional>
#include <vector>

namespace editor {

namespace {

// The translation context of the messages.
class NestedProblemText {
    Q_DECLARE_TR_FUNCTIONS(NestedProblemText)
};

// "the receptivity of T2 of F1", "action 1 of step 3 of F1"; empty when the
// diagnostic names neither.
QString placeText(const core::Diagnostic& d)
{
    const QString step = fromStd(d.element);
    if (d.target == core::Diagnostic::Target::GrafcetTransition)
        //: %1: a GEMMA step; %2: the number of a transition of its nested GRAFCET
        return NestedProblemText::tr("the receptivity of T%2 of %1").arg(step).arg(d.nestedNumber);
    if (d.target == core::Diagnostic::Target::GrafcetStep && d.actionIndex >= 0)
        //: %1: a GEMMA step; %2: a nested step's number; %3: the action's position in its list, from 1
        return NestedProblemText::tr("action %3 of step %2 of %1")
            .arg(step)
            .arg(d.nestedNumber)
            .arg(d.actionIndex + 1);
    return {};
}

// GG405 on three arguments: an undeclared name, or why the action's form
// does not fit its list (an English sentence, never an identifier).
QString actionFormOrUndeclared(const QString& place, const std::string& third)
{
    if (third.find(' ') == std::string::npos)
        return NestedProblemText::tr("In %1: '%2' is not a declared variable.").arg(place, fromStd(third));
    if (third.find("continuous") != std::string::npos)
        return NestedProblemText::tr("In %1: a continuous action is N V or V IF <condition>.").arg(place);
    return NestedProblemText::tr("In %1: a stored action is S V, R V or V := <expression>.").arg(place);
}

QString syntaxOrTypeText(const core::Diagnostic& d, const QString& place)
{
    const std::vector<std::string>& a = d.arguments;
    const std::size_t n = a.size();
    if ((d.code == "GG401" || d.code == "GG404") && n >= 4) {
        const std::optional<core::cond::ParseError> error = core::cond::parseErrorFromArguments(a, 4);
        return NestedProblemText::tr("Syntax error in %1: %2.")
            .arg(place, error ? conditionErrorText(*error) : fromStd(a[3]));
    }
    if (d.code != "GG403" && d.code != "GG405")
        return {};
    if (n == 3)
        return d.code == "GG403"
            ? NestedProblemText::tr("In %1: '%2' is not a declared variable.").arg(place, fromStd(a[2]))
            : actionFormOrUndeclared(place, a[2]);
    if (const std::optional<core::cond::TypeError> error = core::cond::typeErrorFromArguments(a, 4))
        return NestedProblemText::tr("Type error in %1: %2.").arg(place, conditionTypeErrorText(*error));
    if (d.code == "GG405" && n == 4)
        //: %3: an IEC type name (INT)
        return NestedProblemText::tr("In %1: '%2' is %3; this action needs a BOOL variable.")
            .arg(place, fromStd(a[2]), fromStd(a[3]));
    if (d.code == "GG405" && n == 5)
        //: %2: the target variable; %3: its type; %4: the value as written
        return NestedProblemText::tr("In %1: %4 does not fit '%2' (%3): it cannot be assigned to it.")
            .arg(place, fromStd(a[2]), fromStd(a[3]), fromStd(a[4]));
    return {};
}

QString otherText(const core::Diagnostic& d, const QString& place)
{
    const std::vector<std::string>& a = d.arguments;
    const std::size_t n = a.size();
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    const std::string& code = d.code;
    if (code == "GG406" && n == 4)
        //: %2: a step activity as written (X9); %3: its step number; %4: the GEMMA step
        return NestedProblemText::tr("In %1: %2 names step %3, which the GRAFCET of %4 does not have.")
            .arg(place, arg(2), arg(3), arg(0));
    if (code == "GG407" && n == 4)
        //: %2: a duration as written (25d/X1); %3: the longest IEC TIME
        return NestedProblemText::tr("In %1: %2 is longer than %3, the longest duration an IEC TIME (a TON preset) "
                                     "holds.")
            .arg(place, arg(2), arg(3));
    if (code == "GG408" && n == 4)
        //: %2: a division as written (Count / 0)
        return NestedProblemText::tr("In %1: '%2' divides by zero: on the PLC an integer division or MOD by zero "
                                     "stops the task with a fault, and a REAL one gives INF or NaN.")
            .arg(place, arg(2));
    if (code == "GG409" && n == 4)
        //: %2: a division as written (Count / Batch)
        return NestedProblemText::tr("In %1: the divisor of '%2' can be zero: an integer division or MOD by zero "
                                     "stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.")
            .arg(place, arg(2));
    if (code == "GG410" && n == 4)
        //: %2: an edge as written (RE Level)
        return NestedProblemText::tr("In %1: %2 is an edge on a variable that is not BOOL.").arg(place, arg(2));
    if (code == "GG411" && n == 3)
        return NestedProblemText::tr("In %1: %2 is for receptivities only: an action cannot read an edge or a step "
                                     "duration.")
            .arg(place, arg(2));
    if (code == "GG413" && n == 3)
        return NestedProblemText::tr("In %1: '%2' is an input: it is read from the machine, actions never write it.")
            .arg(place, arg(2));
    if (code == "GG414" && n == 4)
        //: %3: an IEC type name (INT)
        return NestedProblemText::tr("In %1: '%2' is %3; a continuous action needs a BOOL variable.")
            .arg(place, arg(2), arg(3));
    if (code == "GG415" && n == 3)
        return NestedProblemText::tr("In %1: '%2' is also driven by continuous actions; a variable has either "
                                     "continuous or stored actions (the stored one is not generated).")
            .arg(place, arg(2));
    if ((code == "GG301" || code == "GG302" || code == "GG303") && n == 3) {
        const QString detail = identifierProblemText(arg(2));
        return detail.isEmpty() ? QString()
                                : NestedProblemText::tr("In %1: invalid variable name: %2.").arg(place, detail);
    }
    if (code == "GG421" && n == 3)
        return NestedProblemText::tr("In %1: the condition reads '%2', a continuous output of the same GRAFCET.")
            .arg(place, arg(2));
    return {};
}

} // namespace

QString nestedProblemText(const core::Diagnostic& diagnostic)
{
    if (diagnostic.code == "GG402" && diagnostic.arguments.size() == 2
        && diagnostic.target == core::Diagnostic::Target::GrafcetTransition)
        return NestedProblemText::tr("The receptivity of T%2 of %1 is empty: write TRUE for a transition that is "
                                     "always ready.")
            .arg(fromStd(diagnostic.element))
            .arg(diagnostic.nestedNumber);
    const QString place = placeText(diagnostic);
    if (place.isEmpty())
        return {};
    if (const QString text = syntaxOrTypeText(diagnostic, place); !text.isEmpty())
        return text;
    return otherText(diagnostic, place);
}

} // namespace editor
