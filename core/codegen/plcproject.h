#pragma once

// The PLC program the Hierarchical Design Pattern turns a model into (spec §6,
// §7), as data: POUs with their declarations and ST bodies, the globals and
// the configuration. The ST text, the plain-ST export and the PLCopen XML
// writer are all printers of this one structure.

#include "core/model/model.h"

#include <string>
#include <string_view>
#include <vector>

namespace core {

// The CODESYS dialect's global variable list (qualified_only): conditions
// read GVL.Start there.
inline constexpr std::string_view kCodesysGlobalList = "GVL";

struct PlcVariable {
    std::string name;
    std::string typeName;     // "BOOL", "UINT", "F1_FB"
    std::string initialValue; // ST literal, empty for none
    std::string comment;      // plain text; printers escape it
};

enum class PouKind { Program, FunctionBlock };

struct PlcPou {
    std::string name; // "GEMMA", "F1_FB"
    PouKind kind = PouKind::Program;
    std::vector<PlcVariable> inputs;
    std::vector<PlcVariable> outputs;
    std::vector<PlcVariable> locals;
    std::vector<PlcVariable> externals; // IEC dialect: the globals this POU reads
    std::string body;                   // ST statements, '\n' line ends, 4-space indent, no trailing blank line
    std::string comment;
};

struct PlcProject {
    std::string projectName;   // the model name
    Dialect dialect = Dialect::Iec;
    std::vector<PlcVariable> globals;
    std::string globalListName; // CODESYS: kCodesysGlobalList; IEC: empty, globals live in the configuration
    std::vector<PlcPou> pous;   // GEMMA first, then the FBs in state order; PackML: the FBs, then the PROGRAM
    std::string configurationName = "GemmaConfiguration";
    std::string resourceName = "GemmaResource";
    std::string taskName = "MainTask";
    std::string programInstanceName = "GemmaInstance";
    int cycleTimeMs = 20;
    int taskPriority = 1;
};

// Where every template's project starts: the model's name and cycle time,
// the dialect, and CODESYS's global variable list.
inline PlcProject startPlcProject(const Model& model, Dialect dialect)
{
    PlcProject project;
    project.projectName = model.settings().name;
    project.dialect = dialect;
    project.cycleTimeMs = model.settings().cycleTimeMs;
    if (dialect == Dialect::Codesys)
        project.globalListName = std::string(kCodesysGlobalList);
    return project;
}

} // namespace core
