#include "core/templates/packml/packmlpreview.h"

#include "core/codegen/nestedpreview.h"
#include "core/codegen/plcproject.h"
#include "core/model/model.h"
#include "core/templates/packml/packmlcodegen.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlprogram.h"

#include <optional>
#include <sstream>

namespace core::packml {

namespace {

// "<number>: (* <name> *)" at `indent` spaces: the number, else nullopt.
std::optional<int> caseLabel(const std::string& line, std::size_t indent)
{
    if (line.size() <= indent || line.compare(0, indent, std::string(indent, ' ')) != 0)
        return std::nullopt;
    std::size_t position = indent;
    int number = 0;
    bool digits = false;
    while (position < line.size() && line[position] >= '0' && line[position] <= '9') {
        number = number * 10 + (line[position] - '0');
        digits = true;
        ++position;
    }
    if (!digits || line.compare(position, 5, ": (* ") != 0)
        return std::nullopt;
    return number;
}

bool isLine(const std::string& line, std::size_t indent, std::string_view text)
{
    return line.size() == indent + text.size() && line.compare(0, indent, std::string(indent, ' ')) == 0
        && line.compare(indent, text.size(), text) == 0;
}

// Walks the second "CASE Mode OF" (section 3): each mode's branch, and each
// state's inside it, runs until the next label or the END_CASE of its level.
void addStateMachineRanges(StPreview& preview)
{
    std::istringstream lines(preview.text);
    std::string line;
    int modeCases = 0;
    std::optional<int> mode;
    std::optional<int> state;
    LineRange modeRange;
    LineRange stateRange;
    const auto closeState = [&](int last) {
        if (mode && state) {
            stateRange.last = last;
            if (const auto found = stateFromNumber(*state))
                preview.ranges[grafcetKey(*mode, *found)] = stateRange;
        }
        state.reset();
    };
    const auto closeMode = [&](int last) {
        closeState(last);
        if (mode) {
            modeRange.last = last;
            preview.ranges[std::to_string(*mode)] = modeRange;
        }
        mode.reset();
    };
    for (int number = 1; std::getline(lines, line); ++number) {
        if (isLine(line, 0, "CASE Mode OF")) {
            ++modeCases;
            continue;
        }
        if (modeCases != 2)
            continue;
        if (isLine(line, 0, "END_CASE;")) {
            closeMode(number - 1);
            break;
        }
        if (const auto label = caseLabel(line, 0)) {
            closeMode(number - 1);
            mode = *label;
            modeRange = {number, number};
        } else if (const auto stateLabel = caseLabel(line, 4); stateLabel && mode) {
            closeState(number - 1);
            state = *stateLabel;
            stateRange = {number, number};
        } else if (isLine(line, 4, "END_CASE;")) {
            closeState(number - 1);
        }
    }
}

} // namespace

StPreview previewPackmlProgram(const Model& model, Dialect dialect)
{
    StPreview preview;
    const PlcProject project = buildPackmlPlcProject(model, dialect);
    for (const PlcPou& pou : project.pous) {
        if (pou.kind == PouKind::Program)
            preview.text = formatPou(pou, dialect);
    }
    addStateMachineRanges(preview);
    return preview;
}

StPreview previewPackmlFunctionBlock(const Model& model, std::string_view key, Dialect dialect)
{
    if (!model.packml() || !model.grafcet(key))
        return {};
    const PackmlProgram program = buildPackmlProgram(model);
    std::string typeName;
    for (const ProgramGrafcet& grafcet : program.grafcets) {
        if (grafcet.key == key)
            typeName = grafcet.typeName;
    }
    if (typeName.empty())
        return {}; // a GRAFCET no enabled state runs: no function block
    const PlcProject project = buildPackmlPlcProject(model, dialect);
    for (const PlcPou& pou : project.pous) {
        if (pou.kind == PouKind::FunctionBlock && pou.name == typeName)
            return previewFunctionBlockPou(pou, dialect);
    }
    return {};
}

} // namespace core::packml
