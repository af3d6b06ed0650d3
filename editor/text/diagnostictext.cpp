#include "editor/text/diagnostictext.h"
#include "editor/text/packmlverificationtext.h"

#include "editor/stdstring.h"
#include "editor/text/conditionerrortext.h"
#include "editor/text/conditiontypeerrortext.h"
#include "editor/text/displaytext.h"
#include "editor/text/elementlabels.h"
#include "editor/text/machinediagnostictext.h"
#include "editor/text/nestedproblemtext.h"
#include "editor/text/packmldiagnostictext.h"
#include "editor/text/valueproblemtext.h"

#include "core/templates/gemma/gemmatemplate.h"
#include "core/model/iectypes.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <optional>
#include <vector>

namespace editor {

namespace {

// The translation context of the messages.
class DiagnosticText {
    Q_DECLARE_TR_FUNCTIONS(DiagnosticText)
};

// A GEMMA transition id as the chart, the docks and the Problems dock name
// it ("F1 → A2" for core's "F1->A2"); other text unchanged.
const QRegularExpression& transitionIdPattern()
{
    static const QRegularExpression pattern(QStringLiteral(R"(\b([A-F]\d?)->([A-F]\d)\b)"));
    return pattern;
}

QString withTransitionLabels(QString text)
{
    QRegularExpressionMatchIterator matches = transitionIdPattern().globalMatch(text);
    QList<QRegularExpressionMatch> found;
    while (matches.hasNext())
        found.prepend(matches.next()); // replaced from the end, so offsets stay valid
    for (const QRegularExpressionMatch& match : found)
        text.replace(match.capturedStart(), match.capturedLength(), transitionLabel(match.captured()));
    return text;
}

QString argumentText(const std::string& argument)
{
    return withTransitionLabels(fromStd(argument));
}

// The English message as the UI shows sentences: capitalised.
QString fallback(const core::Diagnostic& diagnostic)
{
    QString text = withTransitionLabels(fromStd(diagnostic.message));
    if (!text.isEmpty())
        text[0] = text[0].toUpper();
    return text;
}

// Source of a transition id ("F1->A2" -> "F1", "F->D1" -> "F").
QString sourceOf(const std::string& transitionId)
{
    const std::size_t arrow = transitionId.find("->");
    return fromStd(arrow == std::string::npos ? transitionId : transitionId.substr(0, arrow));
}

// The identifier rule a name breaks, in the UI language; the core's detail
// argument is English, so it is derived again from the name.
QString identifierDetail(const QString& name)
{
    switch (core::identifierProblem(name.toStdString())) {
    case core::IdentifierProblem::None:
        break;
    case core::IdentifierProblem::Empty:
        return DiagnosticText::tr("the name is empty");
    case core::IdentifierProblem::InvalidCharacter:
        return DiagnosticText::tr("'%1' is not a valid IEC 61131-3 identifier: use ASCII letters, digits and '_', "
                                  "not starting with a digit")
            .arg(name);
    case core::IdentifierProblem::DoubleUnderscore:
        return DiagnosticText::tr("'%1' contains '__', which IEC 61131-3 identifiers may not").arg(name);
    case core::IdentifierProblem::TrailingUnderscore:
        return DiagnosticText::tr("'%1' ends with '_', which IEC 61131-3 identifiers may not").arg(name);
    case core::IdentifierProblem::Keyword:
        return DiagnosticText::tr("'%1' is an IEC 61131-3 keyword or type name").arg(name);
    case core::IdentifierProblem::GeneratorName:
        return DiagnosticText::tr("'%1' is a name the generated code uses").arg(name);
    }
    return {};
}

QString tokenText(const std::string& code, const QString& transition, const QString& variable)
{
    if (code == "GG208")
        return DiagnosticText::tr("The token on '%2' in %1 is invalid: '%2' does not occur in the condition.")
            .arg(transition, variable);
    if (code == "GG209")
        return DiagnosticText::tr("The token on '%2' in %1 is ambiguous: the condition uses both %2 and NOT %2, so the "
                                  "token could be neither normally open nor normally closed.")
            .arg(transition, variable);
    if (code == "GG211")
        return DiagnosticText::tr("The token in %1 names '%2', which is not a declared variable.")
            .arg(transition, variable);
    if (code == "GG212")
        return DiagnosticText::tr(
            "The token on '%2' in %1 is invalid: '%2' is compared with '=' or '<>' in the condition, "
            "where it has no polarity; a token can only replace a literal %2 or NOT %2.")
            .arg(transition, variable);
    // GG210
    if (sourceOf(transition.toStdString())
        == QLatin1String(core::kFamilySource.data(), static_cast<qsizetype>(core::kFamilySource.size())))
        return DiagnosticText::tr(
            "The token on '%2' in %1 has no effect and is not generated: family transitions never "
            "wait for Complete.")
            .arg(transition, variable);
    return DiagnosticText::tr(
        "The token on '%2' in %1 has no effect and is not generated: its source %3 is a simple step.")
        .arg(transition, variable, sourceOf(transition.toStdString()));
}

// GG306 (on the variable, or on a condition or action that reads it) and
// GG307 (on the step): a variable named like the instance or function block
// the generated code declares for a visible macro-step or enclosing step
// (core/model/stepnames.h). Arguments: the element, the other element,
// "instance" or "function-block", "macro" or "enclosing", the suggested name.
QString stepNameText(const core::Diagnostic& d)
{
    const std::vector<std::string>& a = d.arguments;
    if ((d.code != "GG306" && d.code != "GG307") || a.size() != 5)
        return {};
    const auto arg = [&](std::size_t i) { return argumentText(a[i]); };
    const bool functionBlock = a[2] == "function-block";
    const bool enclosing = a[3] == "enclosing";
    if (d.code == "GG306") {
        if (functionBlock)
            return (enclosing ? DiagnosticText::tr("Variable '%1' has the name of the function block of enclosing "
                                                   "step %2 in the generated code: rename the variable (for example "
                                                   "to '%3').")
                              : DiagnosticText::tr("Variable '%1' has the name of the function block of macro-step "
                                                   "%2 in the generated code: rename the variable (for example to "
                                                   "'%3')."))
                .arg(arg(0), arg(1), arg(4));
        return (enclosing ? DiagnosticText::tr("Variable '%1' has the name of the instance of enclosing step %2 in the "
                                               "generated code: rename the variable (for example to '%3').")
                          : DiagnosticText::tr("Variable '%1' has the name of the instance of macro-step %2 in the "
                                               "generated code: rename the variable (for example to '%3')."))
            .arg(arg(0), arg(1), arg(4));
    }
    const QString declared = functionBlock ? arg(0) + QStringLiteral("_FB") : arg(0);
    if (functionBlock)
        return (enclosing ? DiagnosticText::tr("Enclosing step %1 declares its function block %2 in the generated "
                                               "code, and variable '%3' has that name: rename the variable (for "
                                               "example to '%4'), or make %1 a simple step.")
                          : DiagnosticText::tr("Macro-step %1 declares its function block %2 in the generated code, "
                                               "and variable '%3' has that name: rename the variable (for example to "
                                               "'%4'), or make %1 a simple step."))
            .arg(arg(0), declared, arg(1), arg(4));
    return (enclosing ? DiagnosticText::tr("Enclosing step %1 declares its instance %2 in the generated code, and "
                                           "variable '%3' has that name: rename the variable (for example to '%4'), "
                                           "or make %1 a simple step.")
                      : DiagnosticText::tr("Macro-step %1 declares its instance %2 in the generated code, and variable "
                                           "'%3' has that name: rename the variable (for example to '%4'), or make "
                                           "%1 a simple step."))
        .arg(arg(0), declared, arg(1), arg(4));
}

// GG423 and GG424 (core/checks/grafcetsequencechecks.h).
QString grafcetSequenceText(const core::Diagnostic& d)
{
    const std::vector<std::string>& a = d.arguments;
    const auto arg = [&](std::size_t i) { return argumentText(a[i]); };
    if (d.code == "GG423" && a.size() == 6)
        return (a[5] == "until-stable"
                    //: %2: a BOOL input; %3, %4: two nested transitions; %5: the steps between them
                    ? DiagnosticText::tr("%2 is read in %3 and by its level in %4, which can fire right after it: "
                                         "while %2 stays TRUE, both fire in the same scan and step %5 of %1 is passed "
                                         "through; read its rising edge in %4 (↑%2) so that each press fires one "
                                         "transition.")
                    //: %2: a BOOL input; %3, %4: two nested transitions; %5: the steps between them
                    : DiagnosticText::tr("%2 is read in %3 and by its level in %4, which can fire right after it: "
                                         "while %2 stays TRUE, both fire in consecutive scans and step %5 of %1 is "
                                         "passed through; read its rising edge in %4 (↑%2) so that each press "
                                         "fires one transition."))
            .arg(arg(0), arg(1), arg(2), arg(3), arg(4));
    if (d.code == "GG424" && a.size() == 4)
        //: %3: the branches (T1, T2); %4: values of the variables (CP1 = TRUE, CP2 = FALSE)
        return DiagnosticText::tr("The selection after step %2 of %1 is not complete: with %4 none of %3 fires and "
                                  "the GRAFCET waits in step %2; add a branch for these values unless waiting is "
                                  "intended.")
            .arg(arg(0), arg(1), arg(2), arg(3));
    return {};
}

// The findings about nested GRAFCETs as a whole (core/checks/grafcetchecks.h).
QString nestedGrafcetText(const core::Diagnostic& d)
{
    const std::vector<std::string>& a = d.arguments;
    const std::string& code = d.code;
    const auto arg = [&](std::size_t i) { return argumentText(a[i]); };
    const std::size_t n = a.size();
    if (code == "GG400" && n == 1)
        return DiagnosticText::tr("The nested GRAFCET of %1 has no initial step: it would never do anything.")
            .arg(arg(0));
    if (code == "GG412" && n == 2)
        return DiagnosticText::tr("Step %2 of %1 cannot be reached from the initial steps through transitions: it "
                                  "can never become active.")
            .arg(arg(0), arg(1));
    if (code == "GG416" && n == 2)
        //: %2: the GEMMA transitions that wait for Complete
        return DiagnosticText::tr("The nested GRAFCET of %1 never sets Complete, so %2, which wait for it, can never "
                                  "fire.")
            .arg(arg(0), arg(1));
    if (code == "GG417" && n == 5)
        //: %3, %4: two nested transitions; %5: the values that make both receptivities TRUE
        return DiagnosticText::tr("The selection after step %2 of %1 is not exclusive: %3 and %4 can both fire (with "
                                  "%5), and both branches then start.")
            .arg(arg(0), arg(1), arg(2), arg(3), arg(4));
    if (code == "GG418" && n == 2)
        return DiagnosticText::tr("Step %2 of %1 has no outgoing transition and does not set Complete: the GRAFCET "
                                  "stops there for good.")
            .arg(arg(0), arg(1));
    if (code == "GG419" && n == 3)
        return DiagnosticText::tr("Under the until-stable rule, step %2 of %1 is left in the call that enters it (%3 "
                                  "is always TRUE): the GEMMA layer never sees what it does to Complete.")
            .arg(arg(0), arg(1), arg(2));
    if (code == "GG420" && n == 2)
        //: %2: why, in English (a technical reason)
        return DiagnosticText::tr("Variable '%1' has a name the code of the nested GRAFCETs uses: %2.")
            .arg(arg(0), arg(1));
    if (const QString sequence = grafcetSequenceText(d); !sequence.isEmpty())
        return sequence;
    if (code == "GG422" && n == 2)
        return a[1] == "hidden"
            ? DiagnosticText::tr("The nested GRAFCET of %1 is kept but not used: %1 is hidden.").arg(arg(0))
            : DiagnosticText::tr("The nested GRAFCET of %1 is kept but not used: %1 is a simple step.").arg(arg(0));
    return {};
}

// The translated text, or an empty string when the code has no template
// for this number of arguments.
QString translated(const core::Diagnostic& d)
{
    const std::vector<std::string>& a = d.arguments;
    const std::string& code = d.code;
    // A PackML command or request condition is named in the UI language.
    const auto arg = [&](std::size_t i) {
        return i == 0 && isPackMLCondition(d) ? packmlElementText(d) : argumentText(a[i]);
    };
    const std::size_t n = a.size();

    if (n == 1) {
        if (code == "GG001")
            return DiagnosticText::tr("The initial step %1 is hidden: the PLC would start in a state that has no code.")
                .arg(arg(0));
        if (code == "GG101")
            return DiagnosticText::tr(
                "Step %1 has no visible outgoing transition: the machine would stay in it forever.")
                .arg(arg(0));
        if (code == "GG102")
            return DiagnosticText::tr("Step %1 has no visible incoming transition: it can never become active.")
                .arg(arg(0));
        if (code == "GG202")
            return DiagnosticText::tr("The condition of %1 is empty: write when it fires (TRUE if it is always "
                                      "ready), or hide the transition if your machine does not need it.")
                .arg(arg(0));
        if (code == "GG206")
            return DiagnosticText::tr(
                "The family transition %1 is negated, which has no effect: family transitions never wait "
                "for Complete.")
                .arg(arg(0));
        if (code == "GG214")
            return DiagnosticText::tr("The condition of %1 is FALSE: the transition can never fire (hide it instead).")
                .arg(arg(0));
        if (code == "GG305")
            return DiagnosticText::tr(
                       "Variable '%1' is used by no condition, receptivity or action that generates code.")
                .arg(arg(0));
    }
    if (n == 2) {
        if (code == "GG103")
            return DiagnosticText::tr(
                "Step %1 cannot be reached from the initial step %2 through visible transitions: it can "
                "never become active.")
                .arg(arg(0), arg(1));
        if (code == "GG205")
            return DiagnosticText::tr(
                "Transition %1 is negated, which has no effect: its source %2 is a simple step, and "
                "negation only changes transitions out of macro and enclosing steps.")
                .arg(arg(0), arg(1));
        if (code == "GG208" || code == "GG209" || code == "GG210" || code == "GG211" || code == "GG212")
            return tokenText(code, arg(0), arg(1));
        if (code == "GG213")
            return DiagnosticText::tr("The condition of %1 is TRUE and does not wait for Complete: the lower-priority "
                                      "transitions %2 can never fire.")
                .arg(arg(0), arg(1));
        if (code == "GG301" || code == "GG302" || code == "GG303") {
            const QString detail = identifierDetail(arg(0));
            return detail.isEmpty() ? QString() : DiagnosticText::tr("Invalid variable name: %1.").arg(detail);
        }
    }
    if (const QString nested = nestedGrafcetText(d); !nested.isEmpty())
        return nested;
    if (const QString nested = nestedProblemText(d); !nested.isEmpty())
        return nested;
    if (const QString stepName = stepNameText(d); !stepName.isEmpty())
        return stepName;
    if (code == "GG201" && n >= 3) {
        // The parse error's kind and pieces follow the English detail (docs/diagnostics.md).
        const std::optional<core::cond::ParseError> error = core::cond::parseErrorFromArguments(a, 3);
        return DiagnosticText::tr("Syntax error in the condition of %1: %2.")
            .arg(arg(0), error ? conditionErrorText(*error) : arg(2));
    }
    if (code == "GG204" && n >= 3) {
        // The type error's kind and pieces follow the English detail (docs/diagnostics.md).
        const std::optional<core::cond::TypeError> error = core::cond::typeErrorFromArguments(a, 3);
        return DiagnosticText::tr("Type error in the condition of %1: %2.")
            .arg(arg(0), error ? conditionTypeErrorText(*error) : arg(2));
    }
    if (code == "GG304" && n >= 3) {
        // The value problem's kind and pieces follow the English detail (docs/diagnostics.md).
        const std::optional<core::ValueProblem> problem = core::valueProblemFromArguments(a, 3);
        return DiagnosticText::tr("The default value of variable '%1' is invalid: %2.")
            .arg(arg(0), problem ? valueProblemText(*problem) : arg(2));
    }
    if (n == 3) {
        if (code == "GG203")
            return DiagnosticText::tr("In the condition of %1: '%2' is not a declared variable.").arg(arg(0), arg(1));
        if (code == "GG215")
            //: %2: a division as written (Count / 0)
            return DiagnosticText::tr("In the condition of %1: '%2' divides by zero: on the PLC an integer division "
                                      "or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.")
                .arg(arg(0), arg(1));
        if (code == "GG216")
            //: %2: a division as written (Count / Batch)
            return DiagnosticText::tr("In the condition of %1: the divisor of '%2' can be zero: an integer division or "
                                      "MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives "
                                      "INF or NaN.")
                .arg(arg(0), arg(1));
        if (code == "GG207")
            return DiagnosticText::tr(
                "The token on '%2' in %1 is invalid: '%2' is %3, and only BOOL variables can have a "
                "token.")
                .arg(arg(0), arg(1), arg(2));
    }
    return {};
}

// The findings about the nested GRAFCETs and the user's properties
// (core/verification/bothlayers.cpp words them and lists their arguments),
// or an empty string when the code is none of them or the arguments are not
// those it promises.
QString bothLayersFinding(const core::VerificationFinding& f)
{
    namespace gv = core::verification;
    const std::vector<std::string>& a = f.arguments;
    const std::string& code = f.code;
    const std::size_t n = a.size();
    const auto arg = [&](std::size_t i) { return argumentText(a[i]); };
    if (code == gv::kNestedStepNeverActive && n == 2)
        //: %1: a GEMMA step; %2: the number of a step of its nested GRAFCET
        return DiagnosticText::tr("Step %2 of the nested GRAFCET of %1 can never become active.").arg(arg(0), arg(1));
    if (code == gv::kNestedTransitionDead && n == 2)
        //: %1: a GEMMA step; %2: the number of a transition of its nested GRAFCET
        return DiagnosticText::tr("Transition T%2 of the nested GRAFCET of %1 can never fire.").arg(arg(0), arg(1));
    if (code == gv::kUnsafeNestedStep && n == 2)
        return DiagnosticText::tr("Step %2 of the nested GRAFCET of %1 can be activated while it is already active: "
                                  "the GRAFCET is not safe.")
            .arg(arg(0), arg(1));
    if (code == gv::kUnstableReachable && n == 1)
        return DiagnosticText::tr("The nested GRAFCET of %1 can be Unstable: its evolutions do not settle within one "
                                  "scan.")
            .arg(arg(0));
    if (code == gv::kBranchesTogether && n == 4)
        //: %2: a nested step; %3, %4: the numbers of two nested transitions
        return DiagnosticText::tr("Transitions T%3 and T%4 of the nested GRAFCET of %1 can fire together from step "
                                  "%2: both branches of the selection start.")
            .arg(arg(0), arg(1), arg(2), arg(3));
    if (code == gv::kNeverComplete && n >= 1) {
        QStringList waiting;
        for (std::size_t i = 1; i < n; ++i)
            waiting << arg(i);
        return waiting.isEmpty()
            ? DiagnosticText::tr("Once %1 is active, the inputs can lead its nested GRAFCET to a situation from "
                                 "which Complete never becomes TRUE.")
                  .arg(arg(0))
            //: %2: the GEMMA transitions that wait for Complete
            : DiagnosticText::tr("Once %1 is active, the inputs can lead its nested GRAFCET to a situation from "
                                 "which Complete never becomes TRUE: %2 can no longer fire.")
                  .arg(arg(0), waiting.join(QStringLiteral(", ")));
    }
    if (code == gv::kWaitsForNoComplete && n == 2)
        return DiagnosticText::tr("%1 waits for the Complete of %2, which never becomes TRUE: it can never fire.")
            .arg(arg(0), arg(1));
    if (code == gv::kStoredRace && n == 4)
        return DiagnosticText::tr("Steps %2 and %3 of the nested GRAFCET of %1 can write different values to '%4' "
                                  "in the same scan: the result depends on the order of the actions.")
            .arg(arg(0), arg(1), arg(2), arg(3));
    if (code == gv::kOutputOnEmergencyStop && n == 2)
        return DiagnosticText::tr("The continuous output '%2' can still be TRUE in the scan in which the emergency "
                                  "stop %1 is entered.")
            .arg(arg(0), arg(1));
    if (code == gv::kStoredOutputOnEmergencyStop && n == 2)
        return DiagnosticText::tr("The stored output '%2' can still be TRUE in the scan in which the emergency stop "
                                  "%1 is entered: stored actions are memories, only continuous outputs drop with "
                                  "the state.")
            .arg(arg(0), arg(1));
    // The property texts are the user's, shown as written, cut when too long
    // for a message (the Properties tab holds them whole).
    if (code == gv::kPropertyViolated && n == 1)
        return DiagnosticText::tr("The property '%1' does not hold.").arg(elidedText(fromStd(a[0])));
    if (code == gv::kPropertyHolds && n == 1) {
        // The core says whether the proof rests on abstractions only in its message.
        const bool abstracted = f.message.find("abstractions") != std::string::npos;
        return abstracted ? DiagnosticText::tr("The property '%1' holds in every reachable scan, with "
                                               "the abstractions the verification lists.")
                                .arg(elidedText(fromStd(a[0])))
                          : DiagnosticText::tr("The property '%1' holds in every reachable scan.")
                                .arg(elidedText(fromStd(a[0])));
    }
    if (code == gv::kPropertyUndecided && n == 2)
        //: %2: why, in English (the verifier's reason)
        return DiagnosticText::tr("The property '%1' is undecided: neither proved nor shown violated (%2).")
            .arg(elidedText(fromStd(a[0])), elidedText(fromStd(a[1])));
    if (code == gv::kPropertyUnusable && n == 2)
        return a[1].empty() ? DiagnosticText::tr("The property '%1' cannot be checked: it is empty.")
                                  .arg(elidedText(fromStd(a[0])))
                            //: %2: why, in English (the property checker's message)
                            : DiagnosticText::tr("The property '%1' cannot be checked: %2.")
                                  .arg(elidedText(fromStd(a[0])), elidedText(fromStd(a[1])));
    return {};
}

// The translated text of a finding, or an empty string when the code has no
// template for these arguments.
QString translatedFinding(const core::VerificationFinding& f)
{
    namespace gv = core::verification;
    if (const QString text = bothLayersFinding(f); !text.isEmpty())
        return text;
    // Some findings of the exploration of both layers leave the arguments
    // to the elements (core's convention: the first argument is the element).
    const std::vector<std::string>& a = f.arguments.empty() ? f.elements : f.arguments;
    const std::string& code = f.code;
    const std::size_t n = a.size();
    // The exploration of both layers is undecided as a whole: it names the model.
    if (code == gv::kIncomplete && n == 1 && a[0] == "model")
        return DiagnosticText::tr("The exploration of both layers reached its time or size limit: what it found is "
                                  "reported, but nothing about the nested GRAFCETs or the properties is proved.");
    // The command line's English message names the limit and the codes;
    // here the sentence says what the user may rely on.
    if (code == gv::kIncomplete)
        return n == 0 ? DiagnosticText::tr("The verification reached its time or size limit before every property "
                                           "was decided: the properties not reported were not decided.")
                      : DiagnosticText::tr("The verification reached its time or size limit before deciding "
                                           "everything about %1: what is not reported about it was not decided. "
                                           "Every other finding holds.")
                            .arg(fromStd(a[0]));
    if (n == 0)
        return {};
    const QString element = fromStd(a[0]);
    QStringList others;
    for (std::size_t i = 1; i < n; ++i)
        others << fromStd(a[i]);
    const QString named = others.join(QStringLiteral(", "));

    if (code == gv::kUnreachableStep)
        return n == 1 ? DiagnosticText::tr("Step %1 can never become active: no effective transition leads to it.")
                            .arg(element)
                      : DiagnosticText::tr("Step %1 can never become active: no situation reachable from the "
                                           "initial step lets %2 fire.")
                            .arg(element, named);
    if (code == gv::kDeadTransition)
        return n == 1 ? DiagnosticText::tr("Transition %1 can never fire: its condition is never TRUE in a situation "
                                           "reachable from the initial step.")
                            .arg(element)
                      : DiagnosticText::tr("Transition %1 can never fire: whenever its condition holds, a transition "
                                           "of higher priority fires first (%2).")
                            .arg(element, named);
    if (code == gv::kAlwaysTrue)
        return n == 1 ? DiagnosticText::tr("The condition of %1 is always TRUE: no own transition of an F step can "
                                           "ever fire.")
                            .arg(element)
                      : DiagnosticText::tr("The condition of %1 is always TRUE when %3 is active: %2 can never fire.")
                            .arg(element, named, sourceOf(a[0]));
    if (code == gv::kOverlap && n == 2)
        return DiagnosticText::tr("%1 and %2 can both be TRUE in the same scan: the priority decides, %1 fires.")
            .arg(element, named);
    if (code == gv::kNoReturn)
        return DiagnosticText::tr("Once %1 is active, the inputs can lead to a situation from which the initial step "
                                  "can never become active again.")
            .arg(element);
    if (code == gv::kStuck)
        return DiagnosticText::tr("Step %1 can get stuck: the inputs can lead to a situation in it from which no "
                                  "transition out of it can ever fire.")
            .arg(element);
    if (code == gv::kNoEmergencyStop)
        return n == 1 ? DiagnosticText::tr("The emergency stop D1 can never be entered from %1: the family "
                                           "transition F->D1 is not effective and %1 has no transition to D1.")
                            .arg(element)
                      : DiagnosticText::tr("In some situations of %1 the emergency stop D1 cannot be entered in one "
                                           "scan, whatever the inputs: %2 cannot fire there.")
                            .arg(element, named);
    return {};
}

// A claim that needs a path whose counterexample does not replay is only
// information (core/verification/verification.h).
bool unconfirmed(const core::VerificationFinding& f)
{
    namespace gv = core::verification;
    const bool needsPath = f.code == gv::kOverlap || f.code == gv::kNoReturn || f.code == gv::kStuck
                           || f.code == gv::kNoEmergencyStop;
    return needsPath && f.counterexample && !f.counterexample->confirmed;
}

// Why a finding's run does not replay depends on the analysis that found it:
// an undecidable comparison on the GEMMA layer, Complete free on the GEMMA
// layer of a model whose both layers were explored, or the abstractions of
// the exploration of both layers (timers, numeric memories, comparisons),
// where the core downgrades such a finding to information.
QString unconfirmedReason(const core::VerificationFinding& f)
{
    using core::FindingOrigin;
    const bool notReplayed = f.counterexample && !f.counterexample->confirmed;
    if (f.origin == FindingOrigin::BothLayers && f.severity == core::Severity::Info && notReplayed)
        return f.replaySearchCut
            ? DiagnosticText::tr("Not confirmed: the run found under the abstractions of the verification does not "
                                 "replay in the simulator, and the search for one with time counted in scans stopped "
                                 "at the time or size limit (a longer time limit may find it).")
            : DiagnosticText::tr("Not confirmed: the run found under the abstractions of the verification does "
                                 "not replay in the simulator.");
    if (f.origin == FindingOrigin::GemmaLayerKept && notReplayed)
        return DiagnosticText::tr("Not confirmed: decided on the GEMMA layer with every Complete free, and the run "
                                  "does not replay with the nested GRAFCETs.");
    if (f.origin == FindingOrigin::GemmaLayer && unconfirmed(f))
        return DiagnosticText::tr("Not confirmed: a condition uses a comparison the verifier cannot decide, and the "
                                  "counterexample does not replay.");
    return {};
}

} // namespace

// Transitions named as everywhere else in the editor ("F1 → A2").
QString verificationText(const core::VerificationFinding& finding)
{
    if (QString packml = packmlVerificationText(finding); !packml.isEmpty()) {
        if (finding.counterexample && !finding.counterexample->confirmed)
            packml += QLatin1Char(' ')
                      + DiagnosticText::tr("Not confirmed: its counterexample does not replay to it in the simulator.");
        return packml;
    }
    QString text = withTransitionLabels(translatedFinding(finding));
    if (text.isEmpty()) {
        text = withTransitionLabels(fromStd(finding.message));
        if (!text.isEmpty())
            text[0] = text[0].toUpper();
        return text;
    }
    if (const QString reason = unconfirmedReason(finding); !reason.isEmpty())
        text += QLatin1Char(' ') + reason;
    return text;
}

QString diagnosticText(const core::Diagnostic& diagnostic)
{
    QString text = packmlDiagnosticText(diagnostic);
    if (text.isEmpty())
        text = machineDiagnosticText(diagnostic);
    if (text.isEmpty())
        text = translated(diagnostic);
    return text.isEmpty() ? fallback(diagnostic) : text;
}

QString identifierProblemText(const QString& name)
{
    return identifierDetail(name);
}

QString severityText(core::Severity severity)
{
    switch (severity) {
    case core::Severity::Error:
        return DiagnosticText::tr("Error");
    case core::Severity::Warning:
        return DiagnosticText::tr("Warning");
    case core::Severity::Info:
        return DiagnosticText::tr("Information");
    }
    return {};
}

} // namespace editor
