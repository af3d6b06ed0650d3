#include "editor/text/packmldiagnostictext.h"

#include "editor/stdstring.h"

#include "core/templates/packml/packmlconfiguration.h"

#include <QCoreApplication>

#include <string>
#include <vector>

namespace editor {

namespace {

// The translation context of the messages.
class PackMLDiagnosticText {
    Q_DECLARE_TR_FUNCTIONS(PackMLDiagnosticText)
};

using Arguments = std::vector<std::string>;
using Target = core::Diagnostic::Target;

// PM001, PM003: the model and its settings.
QString settingsText(const std::string& code, const std::string& field, const Arguments& a)
{
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    if (code == "PM001" && a.empty())
        return PackMLDiagnosticText::tr("The model has no unit mode.");
    if (code == "PM001" && a.size() == 1)
        return PackMLDiagnosticText::tr("The initial mode %1 is not a unit mode of the model.").arg(arg(0));
    if (code == "PM003" && field == "initialState" && a.size() == 1)
        return PackMLDiagnosticText::tr("The initial state %1 is not Stopped, Idle or Aborted.").arg(arg(0));
    if (code == "PM003" && field == "name" && a.size() == 2)
        return PackMLDiagnosticText::tr("The model's name '%1' cannot name the PROGRAM (it is no IEC identifier, or "
                                        "the generated code or a variable takes it): the PROGRAM is named %2.")
            .arg(arg(0), arg(1));
    return {};
}

// PM002: a mode's number or name.
QString modeNumberText(const Arguments& a)
{
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    const std::string& reason = a.size() >= 2 ? a[1] : std::string();
    if (reason == "out-of-range" && a.size() == 2)
        return PackMLDiagnosticText::tr("Unit mode %1 is outside 1..31 (PackTags UnitMode).").arg(arg(0));
    if (reason == "repeated" && a.size() == 2)
        return PackMLDiagnosticText::tr("Unit mode %1 is given twice.").arg(arg(0));
    if (reason == "fixed-name" && a.size() == 3) {
        const QString fixed = fromStd(std::string(core::packml::baseModeName(fromStd(a[0]).toInt())));
        //: %2: the fixed name of a base mode (Production, Maintenance, Manual)
        return PackMLDiagnosticText::tr("Unit mode %1 is named %2, not '%3'.").arg(arg(0), fixed, arg(2));
    }
    if (reason == "not-identifier" && a.size() == 3)
        return PackMLDiagnosticText::tr("The name '%2' of unit mode %1 is not an IEC identifier, and it becomes part "
                                        "of the names of function blocks.")
            .arg(arg(0), arg(2));
    if (reason == "reserved" && a.size() == 3)
        return PackMLDiagnosticText::tr("The name '%2' of unit mode %1 is one the generated code uses.")
            .arg(arg(0), arg(2));
    if (reason == "duplicate-name" && a.size() == 4)
        return PackMLDiagnosticText::tr("Unit mode %1 is named '%2', as mode %3 is (ignoring case).")
            .arg(arg(0), arg(2), arg(3));
    return {};
}

// PM004-PM009: what a mode lists, and where its transitions lead.
QString modeText(const std::string& code, const Arguments& a)
{
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    const std::size_t n = a.size();
    if (code == "PM004" && n == 2)
        return PackMLDiagnosticText::tr("Mode %1 lists %2 as disabled, which every unit needs: ignored.")
            .arg(arg(0), arg(1));
    if (code == "PM005" && n == 3)
        //: %3: the enabled acting states of the loop (Holding, Unholding)
        return PackMLDiagnosticText::tr("Mode %1 lists %2 as disabled, but it stays enabled while %3 is enabled.")
            .arg(arg(0), arg(1), arg(2));
    if (code == "PM006" && n == 3 && a[2] == "acting")
        return PackMLDiagnosticText::tr("Mode %1 allows a mode change in %2, an acting state, half-way through its "
                                        "GRAFCET: ignored.")
            .arg(arg(0), arg(1));
    if (code == "PM006" && n == 3 && a[2] == "disabled")
        return PackMLDiagnosticText::tr("Mode %1 allows a mode change in %2, which it disables: no effect.")
            .arg(arg(0), arg(1));
    if (code == "PM007" && n == 1)
        return PackMLDiagnosticText::tr("Mode %1 can never be current: it is not the initial mode, and no state "
                                        "allows a change into it from another mode.")
            .arg(arg(0));
    if (code == "PM008" && n == 1)
        return PackMLDiagnosticText::tr("In mode %1, no sequence of transitions leads to Execute from where the mode "
                                        "begins (counting a State Complete only where the state's GRAFCET writes "
                                        "Complete).")
            .arg(arg(0));
    if (code == "PM009" && n == 2)
        return PackMLDiagnosticText::tr("In mode %1, no sequence of transitions reaches %2 from where the mode "
                                        "begins: it is never active.")
            .arg(arg(0), arg(1));
    return {};
}

// PM010, PM014-PM016: the GRAFCETs of the states.
QString grafcetText(const std::string& code, const Arguments& a)
{
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    const std::size_t n = a.size();
    if (code == "PM010" && n == 2 && a[1] == "Aborting")
        return PackMLDiagnosticText::tr("The GRAFCET of %1: Aborting never writes Complete: nothing leaves Aborting, "
                                        "so the unit can never reach Aborted.")
            .arg(arg(0));
    if (code == "PM010" && n == 2)
        return PackMLDiagnosticText::tr("The GRAFCET of %1: %2 never writes Complete: only Stop or Abort leave the "
                                        "state.")
            .arg(arg(0), arg(1));
    if (code == "PM014" && n == 2)
        return PackMLDiagnosticText::tr("The GRAFCET of %1: %2 is kept, but the mode disables the state: it "
                                        "generates no code.")
            .arg(arg(0), arg(1));
    if (code == "PM015" && n == 4) {
        const QString why = a[3] == "no-mode" ? PackMLDiagnosticText::tr("there is no mode %1").arg(arg(2))
            : a[3] == "itself"              ? PackMLDiagnosticText::tr("that is the mode itself")
                                            : PackMLDiagnosticText::tr("mode %1 has no GRAFCET of its own there")
                                                  .arg(arg(2));
        //: %4: why (there is no mode 9, that is the mode itself, ...)
        return PackMLDiagnosticText::tr("%1: %2 runs the same GRAFCET as mode %3, but %4.")
            .arg(arg(0), arg(1), arg(2), why);
    }
    if (code == "PM016" && n == 1)
        return PackMLDiagnosticText::tr("The GRAFCET of %1: Execute writes Complete, which nothing reads in the 2022 "
                                        "edition: use the Complete command.")
            .arg(arg(0));
    return {};
}

// PM011-PM013, PM017, PM019, GG202: the commands and requests.
QString commandText(const core::Diagnostic& d)
{
    const Arguments& a = d.arguments;
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    const std::size_t n = a.size();
    const std::string& code = d.code;
    const QString place = packmlElementText(d);
    if (code == "GG202" && d.target == Target::Command && n == 1)
        return PackMLDiagnosticText::tr("The condition of %1 is empty: write FALSE for a command that comes only "
                                        "through CntrlCmd.")
            .arg(place);
    if (code == "PM011" && n == 2 && d.target == Target::Command)
        return PackMLDiagnosticText::tr("Command %2 has the same condition as command %1: one rising edge issues "
                                        "both, and only the first in priority acts.")
            .arg(arg(0), arg(1));
    if (code == "PM011" && n == 2 && d.target == Target::Request)
        return PackMLDiagnosticText::tr("The request of mode %2 has the same condition as the request of mode %1: "
                                        "one rising edge issues both, and only the first in priority acts.")
            .arg(arg(0), arg(1));
    if (code == "PM012" && n == 2)
        return PackMLDiagnosticText::tr("The condition of %1 reads the output '%2': commands and mode requests come "
                                        "from an operator, a line controller or an alarm, so read an input or an "
                                        "internal variable.")
            .arg(place, arg(1));
    if (code == "PM013" && n == 1)
        return PackMLDiagnosticText::tr("No enabled state of any mode accepts the command %1: it generates no code.")
            .arg(arg(0));
    if (code == "PM017" && n == 2 && a[1] == "condition")
        return PackMLDiagnosticText::tr("The Complete command exists in the 2022 edition only: its setting is "
                                        "ignored in this 2015 model.");
    if (code == "PM017" && n == 2)
        return PackMLDiagnosticText::tr("The option completeInSuspendedHeld is for the 2022 edition only: it is "
                                        "ignored in this 2015 model.");
    if (code == "PM019" && n == 3) {
        const QString what = a[2] == "step-activity" ? PackMLDiagnosticText::tr("a step activity")
            : a[2] == "step-duration"                ? PackMLDiagnosticText::tr("a step duration")
            : a[2] == "complete"                     ? QStringLiteral("Complete")
                                                     : PackMLDiagnosticText::tr("an edge");
        //: %2: what the condition uses (a step activity, an edge...); %3: the text as written
        return PackMLDiagnosticText::tr("The condition of %1 uses %2 ('%3'), which only the texts of nested GRAFCETs "
                                        "have; a command or request is already the rising edge of its condition.")
            .arg(place, what, arg(1));
    }
    return {};
}

} // namespace

QString packmlElementText(const core::Diagnostic& d)
{
    const QString element = fromStd(d.element);
    switch (d.target) {
    case Target::Mode:
        //: A unit mode of a PackML model: "mode Manual"
        return PackMLDiagnosticText::tr("mode %1").arg(element);
    case Target::Command:
        //: A PackML command: "command Hold"
        return PackMLDiagnosticText::tr("command %1").arg(element);
    case Target::ModeState:
        //: A state in a unit mode: "Manual: Execute"
        return PackMLDiagnosticText::tr("%1: %2").arg(element, fromStd(d.state));
    case Target::Request:
        //: The request condition of a unit mode
        return PackMLDiagnosticText::tr("request of mode %1").arg(element);
    default:
        return {};
    }
}

bool isPackMLCondition(const core::Diagnostic& d)
{
    return d.target == Target::Command || d.target == Target::Request;
}

QString packmlDiagnosticText(const core::Diagnostic& d)
{
    const Arguments& a = d.arguments;
    if (d.code == "PM018" && a.size() == 2)
        return PackMLDiagnosticText::tr("The variable name '%1' is one the generated PackML code uses (PackTags, the "
                                        "state machine, the function blocks or the program %2).")
            .arg(fromStd(a[0]), fromStd(a[1]));
    if (d.code == "PM002")
        return modeNumberText(a);
    if (const QString text = settingsText(d.code, d.field, a); !text.isEmpty())
        return text;
    if (const QString text = modeText(d.code, a); !text.isEmpty())
        return text;
    if (const QString text = grafcetText(d.code, a); !text.isEmpty())
        return text;
    return commandText(d);
}

} // namespace editor
