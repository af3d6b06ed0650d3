#include "editor/machine/machinetext.h"

#include <QCoreApplication>

namespace editor::machinetext {

namespace {

// The translation context of these words.
class MachineText {
    Q_DECLARE_TR_FUNCTIONS(MachineText)
};

} // namespace

QString kindName(core::machine::ComponentKind kind)
{
    using Kind = core::machine::ComponentKind;
    switch (kind) {
    case Kind::DoubleActingCylinder: return MachineText::tr("Double-acting cylinder");
    case Kind::SingleActingCylinder: return MachineText::tr("Single-acting cylinder");
    case Kind::Conveyor: return MachineText::tr("Conveyor");
    case Kind::Lamp: return MachineText::tr("Lamp");
    case Kind::PushButton: return MachineText::tr("Push button");
    case Kind::Selector: return MachineText::tr("Selector");
    case Kind::EmergencyStop: return MachineText::tr("Emergency stop");
    case Kind::DelayedSensor: return MachineText::tr("Delayed sensor");
    case Kind::PartSource: return MachineText::tr("Part source");
    }
    return {};
}

QString roleName(std::string_view roleKey)
{
    if (roleKey == "extend")
        return MachineText::tr("extend");
    if (roleKey == "retract")
        return MachineText::tr("retract");
    if (roleKey == "retracted")
        return MachineText::tr("retracted");
    if (roleKey == "extended")
        return MachineText::tr("extended");
    if (roleKey == "run")
        return MachineText::tr("run");
    if (roleKey == "partPresent")
        return MachineText::tr("part present");
    if (roleKey == "lamp")
        return MachineText::tr("lamp");
    if (roleKey == "input")
        return MachineText::tr("input");
    if (roleKey == "output")
        return MachineText::tr("output");
    if (roleKey == "sensor")
        return MachineText::tr("sensor");
    if (roleKey == "empty")
        return MachineText::tr("empty");
    return QString::fromUtf8(roleKey.data(), static_cast<qsizetype>(roleKey.size()));
}

QString parameterName(std::string_view parameterKey)
{
    if (parameterKey == "extendMs")
        return MachineText::tr("Extend time (ms)");
    if (parameterKey == "retractMs")
        return MachineText::tr("Retract time (ms)");
    if (parameterKey == "travelMs")
        return MachineText::tr("Travel time (ms)");
    if (parameterKey == "onDelayMs")
        return MachineText::tr("On delay (ms)");
    if (parameterKey == "offDelayMs")
        return MachineText::tr("Off delay (ms)");
    if (parameterKey == "parts")
        return MachineText::tr("Parts");
    return QString::fromUtf8(parameterKey.data(), static_cast<qsizetype>(parameterKey.size()));
}

QString contactName(core::machine::Contact contact)
{
    return contact == core::machine::Contact::NormallyClosed ? MachineText::tr("Normally closed")
                                                             : MachineText::tr("Normally open");
}

} // namespace editor::machinetext
