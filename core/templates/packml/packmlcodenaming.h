#pragma once

// How the generated PackML code spells the globals it reads (spec packml.md
// §6, §6.7): by their declared name in the IEC dialect, GVL.<name> in the
// CODESYS one, with the read ones collected for each POU's VAR_EXTERNAL.
// Shared by the PROGRAM and the function blocks of packmlcodegen.

#include "core/codegen/plcproject.h"
#include "core/condition/symboltable.h"
#include "core/templates/packml/packmlprogram.h"

#include <string>
#include <string_view>
#include <vector>

namespace core::packml {

// The name each global of program.variables is declared under: its own, or
// Invalid_Name_<position> when the code cannot declare it (an IEC keyword or
// not an identifier, or a name of spec §5.3: PM018). No usable condition
// reads such a variable, so the new name only has to be fresh.
std::vector<std::string> declaredGlobalNames(const PackmlProgram& program);

class PackmlNaming {
public:
    PackmlNaming(const PackmlProgram& program, const std::vector<std::string>& declared, Dialect dialect);

    // "Cmd_Start" or "GVL.Cmd_Start"; records the read.
    std::string global(std::string_view name);
    // "Start_PREV" or "GVL.Start_PREV".
    std::string edgeMemory(std::string_view name) const;
    // The globals read so far, slot order, as declared (no comments).
    std::vector<PlcVariable> readVariables() const;
    // The same, the user variables only: the PROGRAM declares the six
    // PackTags whether it reads them or not (spec §6.2).
    std::vector<PlcVariable> readUserVariables(std::size_t userCount) const;

private:
    std::string qualified(std::string name) const;

    const PackmlProgram& m_program;
    const std::vector<std::string>& m_declared;
    SymbolTable m_symbols;
    Dialect m_dialect;
    std::vector<bool> m_read;
};

} // namespace core::packml
