#include "core/codegen/nestedpreview.h"

#include "core/codegen/plcproject.h"

#include <regex>
#include <sstream>

namespace core {

namespace {

// The element a line of the FB belongs to: "X3", "T2", or empty. `block`
// carries an open IF GG_Left3 / GG_Entered3 block over to the next lines.
std::string elementOfLine(const std::string& line, std::string& block)
{
    static const std::regex statement(R"(^\s*(X|GG_Fire|GG_Left|GG_Entered)(\d+)\s*:[=\s])");
    static const std::regex ifBlock(R"(^\s*IF (GG_Left|GG_Entered)(\d+) THEN\s*$)");
    static const std::regex endIf(R"(^\s*END_IF;\s*$)");
    std::smatch match;
    if (!block.empty()) {
        std::string inside = block;
        if (std::regex_match(line, endIf))
            block.clear();
        return inside;
    }
    if (std::regex_match(line, match, ifBlock)) {
        block = "X" + match[2].str();
        return block;
    }
    if (std::regex_search(line, match, statement))
        return (match[1].str() == "GG_Fire" ? "T" : "X") + match[2].str();
    return {};
}

void addRange(StPreview& preview, std::map<std::string, int>& runs, const std::string& key, LineRange range)
{
    const int run = ++runs[key];
    preview.ranges.emplace(run == 1 ? key : key + "@" + std::to_string(run), range);
}

} // namespace

StPreview previewNestedFunctionBlock(const Model& model, std::string_view stepId, Dialect dialect)
{
    StPreview preview;
    const PlcProject project = buildPlcProject(model, dialect);
    const std::string name = std::string(stepId) + "_FB";
    const PlcPou* pou = nullptr;
    for (const PlcPou& candidate : project.pous) {
        if (candidate.kind == PouKind::FunctionBlock && candidate.name == name)
            pou = &candidate;
    }
    if (!pou || !model.effectiveGrafcet(stepId))
        return preview;
    return previewFunctionBlockPou(*pou, dialect);
}

StPreview previewFunctionBlockPou(const PlcPou& pou, Dialect dialect)
{
    StPreview preview;
    preview.text = formatPou(pou, dialect);

    std::istringstream lines(preview.text);
    std::string line;
    std::string block;
    std::string runKey;
    LineRange run;
    std::map<std::string, int> runs;
    for (int number = 1; std::getline(lines, line); ++number) {
        const std::string key = elementOfLine(line, block);
        if (key == runKey && !key.empty()) {
            run.last = number;
            continue;
        }
        if (!runKey.empty())
            addRange(preview, runs, runKey, run);
        runKey = key;
        run = {number, number};
    }
    if (!runKey.empty())
        addRange(preview, runs, runKey, run);
    return preview;
}

} // namespace core
