#include "editor/text/machinediagnostictext.h"

#include "editor/stdstring.h"

#include <QCoreApplication>

#include <vector>

namespace editor {

namespace {

// The translation context of the messages.
class MachineDiagnosticText {
    Q_DECLARE_TR_FUNCTIONS(MachineDiagnosticText)
};

// A variable kind as core names it ("input", "output", "internal").
QString kindText(const std::string& kind)
{
    if (kind == "input")
        return MachineDiagnosticText::tr("an input");
    if (kind == "output")
        return MachineDiagnosticText::tr("an output");
    return MachineDiagnosticText::tr("an internal variable");
}

} // namespace

QString machineDiagnosticText(const core::Diagnostic& d)
{
    const std::vector<std::string>& a = d.arguments;
    const std::string& code = d.code;
    const std::size_t n = a.size();
    const auto arg = [&](std::size_t i) { return fromStd(a[i]); };
    if (code == "GG601" && n == 3)
        //: %1: a machine component; %2: its role (extend, retracted...); %3: a name
        return MachineDiagnosticText::tr("%1's %2 signal names '%3', which is no variable of the model.")
            .arg(arg(0), arg(1), arg(2));
    if (code == "GG602" && n == 5)
        //: %1: a machine component; %2: its role; %3: a variable; %4, %5: "an input", "an output"...
        return MachineDiagnosticText::tr("%1's %2 signal is %3, %4; it needs %5.")
            .arg(arg(0), arg(1), arg(2), kindText(a[3]), kindText(a[4]));
    if (code == "GG603" && n == 4)
        //: %4: an IEC type (INT)
        return MachineDiagnosticText::tr("%1's %2 signal is %3, of type %4; a machine signal is BOOL.")
            .arg(arg(0), arg(1), arg(2), arg(3));
    if (code == "GG604" && n == 5)
        //: %1, %4: machine components; %2, %5: their roles; %3: the input both are wired to
        return MachineDiagnosticText::tr("%3 is wired to %1's %2 signal and to %4's %5 signal: an input has one "
                                         "source.")
            .arg(arg(0), arg(1), arg(2), arg(3), arg(4));
    if (code == "GG605" && n == 3)
        return MachineDiagnosticText::tr("%1's %2 signal %3 is driven by no action of the program: the component "
                                         "never moves.")
            .arg(arg(0), arg(1), arg(2));
    if (code == "GG606" && n == 3)
        //: %2: a parameter (extendMs, onDelayMs, parts); %3: its value
        return MachineDiagnosticText::tr("%1's %2 is %3: out of range (travel times 1 to 3600000 ms, delays 0 to "
                                         "3600000 ms, parts 0 to 1000000000).")
            .arg(arg(0), arg(1), arg(2));
    if (code == "GG607" && n == 2)
        return MachineDiagnosticText::tr("%1 has no variable for its %2 signal.").arg(arg(0), arg(1));
    if (code == "GG608" && n == 2)
        return MachineDiagnosticText::tr("%1 feeds '%2', which is no conveyor of the machine.").arg(arg(0), arg(1));
    return {};
}

} // namespace editor
