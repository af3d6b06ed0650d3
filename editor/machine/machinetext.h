#pragma once

// The words the editor shows for the virtual machine's kinds, roles and
// parameters (core/machine/componentkind.h spells them as file keys), in
// the UI language: the Machine tab and the Machine dock say the same.

#include "core/machine/componentkind.h"

#include <QString>

#include <string_view>

namespace editor::machinetext {

QString kindName(core::machine::ComponentKind kind);          // "Double-acting cylinder"
QString roleName(std::string_view roleKey);                   // "extended limit switch"
QString parameterName(std::string_view parameterKey);         // "Extend time (ms)"
QString contactName(core::machine::Contact contact);          // "Normally open"

} // namespace editor::machinetext
