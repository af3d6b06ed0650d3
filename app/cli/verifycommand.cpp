#include "verifycommand.h"

#include "cycletime.h"
#include "loadreport.h"
#include "terminal.h"

#include "core/formats/fileio.h"
#include "core/templates/gemma/gemmaprogram.h"
#include "core/model/model.h"
#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlpromela.h"
#include "core/verification/bothlayers.h"
#include "core/verification/promela.h"
#include "core/verification/promelaprogram.h"
#include "core/verification/property.h"
#include "core/verification/verification.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace cli {

namespace {

// "GV102-F1-F5.scenario": the code and the first element(s), file-name safe.
std::string counterexampleName(const core::VerificationFinding& finding, std::set<std::string>& used)
{
    std::string base = finding.code;
    const std::size_t named = finding.code == core::verification::kOverlap ? 2 : 1;
    for (std::size_t i = 0; i < finding.elements.size() && i < named; ++i) {
        base += "-";
        for (char c : finding.elements[i]) {
            const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
            if (plain)
                base += c;
            else if (base.back() != '-')
                base += '-';
        }
    }
    std::string name = base + ".scenario";
    for (int n = 2; used.count(name); ++n)
        name = base + "-" + std::to_string(n) + ".scenario";
    used.insert(name);
    return name;
}

std::string joined(const std::vector<std::string>& ids)
{
    std::string text;
    for (const std::string& id : ids)
        text += (text.empty() ? "" : ", ") + id;
    return text;
}

// Why `id` cannot be assumed automatic, empty when it can: only a visible
// macro or enclosing step has a Complete output in the generated program,
// and one with a nested GRAFCET takes it from its GRAFCET.
std::string notNestedReason(const core::Model& model, const std::string& id)
{
    const core::Step* step = model.step(id);
    if (!step)
        return "no step '" + id + "' in the model";
    if (step->type == core::StepType::Simple)
        return id + " is a simple step: it has no Complete";
    if (step->hidden)
        return id + " is hidden: it is not in the generated program";
    if (model.effectiveGrafcet(id))
        return id + " has a nested GRAFCET: its Complete comes from the GRAFCET, not from an assumption";
    return {};
}

// The steps whose Complete can be assumed: visible macro and enclosing steps
// without nested GRAFCET, state order.
std::vector<std::string> nestedSteps(const core::Model& model)
{
    std::vector<std::string> nested;
    for (const core::GemmaStep& step : core::buildGemmaProgram(model).steps) {
        if (step.hasNestedBehaviour() && !step.nested)
            nested.push_back(step.id);
    }
    return nested;
}

// --complete-automatic STEP[,STEP...] or `all`: the steps assumed automatic,
// in state order; nullopt with a message on `err`.
std::optional<std::vector<std::string>> parseCompleteAutomatic(const std::string& value, const core::Model& model,
                                                               std::ostream& err)
{
    const std::vector<std::string> nested = nestedSteps(model);
    if (value == "all")
        return nested;
    std::set<std::string> ids;
    std::istringstream items(value);
    for (std::string id; std::getline(items, id, ',');) {
        if (id.empty())
            break;
        if (const std::string reason = notNestedReason(model, id); !reason.empty()) {
            err << "ggstudio-cli: --complete-automatic: " << reason << " (steps it applies to: "
                << (nested.empty() ? std::string("none") : joined(nested)) << ")" << lineEnd;
            return std::nullopt;
        }
        ids.insert(id);
    }
    if (ids.empty() || items) {
        err << "ggstudio-cli: --complete-automatic takes step ids separated by commas, or all" << lineEnd;
        return std::nullopt;
    }
    std::vector<std::string> automatic;
    for (const std::string& id : nested) {
        if (ids.count(id))
            automatic.push_back(id);
    }
    return automatic;
}

// What --promela writes: both layers when the run explores them (nested
// GRAFCETs or properties), else the GEMMA layer with its probes.
// The run's time limit, written as a duration (`30s`, `2m`, `1500ms`): from 1 ms to one
// hour, so that every run stays bounded.
std::optional<std::chrono::milliseconds> parseTimeLimit(const std::string& text)
{
    constexpr int kMaxMs = 60 * 60 * 1000;
    const std::optional<int> ms = parseCycleTime(text);
    if (!ms || *ms < 1 || *ms > kMaxMs)
        return std::nullopt;
    return std::chrono::milliseconds(*ms);
}

// A PackML model: its program, time counted in scans (docs/packml.md, "SPIN
// cross-check"); `unsupported` says why it cannot be written.
std::string promelaText(const core::Model& model, const core::VerificationOptions& options, std::string& unsupported)
{
    if (model.templateKind() == core::TemplateKind::PackML) {
        core::packml::PackmlPromela exported = core::packml::buildPackmlPromela(model);
        unsupported = std::move(exported.unsupported);
        return std::move(exported.text);
    }
    if (!core::needsBothLayers(model, options)) {
        core::PromelaOptions gemma;
        gemma.complete = options.complete;
        return core::exportPromela(model, gemma);
    }
    core::ProgramPromelaOptions program;
    program.complete = options.complete;
    program.properties = core::propertiesToCheck(model, options);
    program.exactTime = options.exactTime;
    if (core::runsClosedLoop(model, options)) {
        program.machine = &model.machine();
        program.singleFaults = options.faults == core::VerificationOptions::Faults::Single;
    }
    return core::buildProgramPromela(model, program).text;
}

// Writes a counterexample that replays, and says where; one that does not
// replay is not written (it would show nothing). False when the write failed,
// which is reported on `err`.
bool writeCounterexample(const core::Counterexample& counterexample, const core::VerificationFinding& finding,
                         const std::string& directory, std::set<std::string>& used, Streams streams)
{
    if (!counterexample.confirmed) {
        streams.out << "    counterexample: not written: its run does not replay in the simulator" << lineEnd;
        return true;
    }
    const std::string file = (std::filesystem::path(directory) / counterexampleName(finding, used)).string();
    if (core::Status status = core::writeFileAtomically(file, counterexample.text); !status) {
        streams.err << file << ": " << status.message << lineEnd;
        streams.out << "    counterexample: not written: " << file << ": " << status.message << lineEnd;
        return false;
    }
    streams.out << "    counterexample: " << file << " (" << counterexample.scans << " scans)" << lineEnd;
    return true;
}

const char* outcomeName(core::PropertyOutcome outcome)
{
    switch (outcome) {
    case core::PropertyOutcome::Holds: return "holds";
    case core::PropertyOutcome::Violated: return "violated";
    case core::PropertyOutcome::Undecided: return "undecided";
    }
    return "undecided";
}

// "property 2 'never Count > 2': undecided (why)", one line per property.
void printPropertyVerdicts(const std::string& path, const core::VerificationResult& result, std::ostream& out)
{
    for (std::size_t i = 0; i < result.propertyVerdicts.size() && i < result.properties.size(); ++i) {
        const core::PropertyVerdict& verdict = result.propertyVerdicts[i];
        out << path << ": property " << i + 1 << " '" << result.properties[i] << "': " << outcomeName(verdict.outcome);
        if (!verdict.reason.empty())
            out << " (" << verdict.reason << ")";
        out << lineEnd;
    }
}

} // namespace

int commandVerify(const Arguments& args, Streams streams)
{
    if (args.positional().size() != 1) {
        streams.err << "ggstudio-cli: verify takes one model file" << lineEnd << "Try 'ggstudio-cli --help'."
                    << lineEnd;
        return UsageError;
    }
    const std::string& path = args.positional()[0];
    const std::optional<std::string> directory = args.value("--counterexamples");
    if (directory && directory->empty()) {
        streams.err << "ggstudio-cli: --counterexamples needs a directory" << lineEnd << "Try 'ggstudio-cli --help'."
                    << lineEnd;
        return UsageError;
    }
    if (directory && *directory == "-") {
        streams.err << "ggstudio-cli: --counterexamples writes a folder: standard output carries the findings"
                    << lineEnd << "Try 'ggstudio-cli --help'." << lineEnd;
        return UsageError;
    }
    core::LoadedModel loaded = loadAndReport(path, streams.err, core::TemplateSupport::GemmaAndPackML);
    if (!loaded.ok())
        return UnreadableInput;
    if (loaded.model->templateKind() == core::TemplateKind::PackML) {
        for (const char* gemmaOnly : {"--complete-automatic", "--machine"}) {
            if (args.has(gemmaOnly) || args.value(gemmaOnly)) {
                streams.err << "ggstudio-cli: " << gemmaOnly << " is not available for PackML models" << lineEnd
                            << "Try 'ggstudio-cli --help'." << lineEnd;
                return UsageError;
            }
        }
    }
    const bool closedLoop = args.has("--machine");
    const std::optional<std::string> faults = args.value("--faults");
    if (faults && *faults != "single") {
        streams.err << "ggstudio-cli: --faults '" << *faults << "': the only kind is single (--faults single)"
                    << lineEnd << "Try 'ggstudio-cli --help'." << lineEnd;
        return UsageError;
    }
    if (faults && !closedLoop) {
        streams.err << "ggstudio-cli: --faults single needs --machine: faults are injected into the model's machine"
                    << lineEnd << "Try 'ggstudio-cli --help'." << lineEnd;
        return UsageError;
    }
    if (closedLoop && loaded.model->machine().empty()) {
        streams.err << "ggstudio-cli: --machine: " << path
                    << " has no machine to verify with (docs/simulation.md, \"The virtual machine\")" << lineEnd;
        return UsageError;
    }
    std::vector<std::string> automatic;
    if (const std::optional<std::string> value = args.value("--complete-automatic")) {
        std::optional<std::vector<std::string>> steps = parseCompleteAutomatic(*value, *loaded.model, streams.err);
        if (!steps)
            return UsageError;
        automatic = std::move(*steps);
    }
    core::VerificationOptions options;
    for (const std::string& id : automatic)
        options.complete[id] = core::CompleteAssumption::Automatic;
    options.exactTime = args.has("--exact-time");
    options.closedLoop = closedLoop;
    if (faults)
        options.faults = core::VerificationOptions::Faults::Single;
    if (const std::optional<std::string> limit = args.value("--time-limit")) {
        const std::optional<std::chrono::milliseconds> parsed = parseTimeLimit(*limit);
        if (!parsed) {
            streams.err << "ggstudio-cli: --time-limit '" << *limit
                        << "': give a duration from 1ms to 1h, such as 30s or 2m" << lineEnd
                        << "Try 'ggstudio-cli --help'." << lineEnd;
            return UsageError;
        }
        options.timeLimit = *parsed;
    }
    for (const std::string& property : args.values("--property")) {
        const std::vector<core::PropertyProblem> problems
            = core::checkProperty(*loaded.model, property, core::PropertyAtoms{faults.has_value()});
        if (!problems.empty()) {
            streams.err << "ggstudio-cli: --property '" << property << "': column " << problems.front().span.begin + 1
                        << ": " << problems.front().message << lineEnd;
            return UsageError;
        }
        options.properties.push_back(property);
    }
    if (directory) {
        if (core::Status target = core::checkFolderTarget(*directory); !target) {
            streams.err << *directory << ": " << target.message << lineEnd;
            return UnreadableInput;
        }
        std::error_code error;
        std::filesystem::create_directories(*directory, error);
        if (error) {
            streams.err << *directory << ": cannot create the directory: " << error.message() << lineEnd;
            return UnreadableInput;
        }
    }
    if (const std::optional<std::string> promela = args.value("--promela")) {
        if (promela->empty()) {
            streams.err << "ggstudio-cli: --promela needs an output file" << lineEnd << "Try 'ggstudio-cli --help'."
                    << lineEnd;
            return UsageError;
        }
        if (*promela == "-") {
            streams.err << "ggstudio-cli: --promela writes a file: standard output carries the findings" << lineEnd
                        << "Try 'ggstudio-cli --help'." << lineEnd;
            return UsageError;
        }
        std::string unsupported;
        const std::string text = promelaText(*loaded.model, options, unsupported);
        if (!unsupported.empty()) {
            streams.err << *promela << ": not written: the program cannot be exported: " << unsupported << lineEnd;
            return UnreadableInput;
        }
        if (core::Status status = core::writeFileAtomically(*promela, text); !status) {
            streams.err << *promela << ": " << status.message << lineEnd;
            return UnreadableInput;
        }
    }
    const core::VerificationResult result = core::verifyModel(*loaded.model, options);
    bool writeFailed = false;
    std::set<std::string> used;
    for (const core::VerificationFinding& finding : result.findings) {
        streams.out << path << ": " << core::verificationElementLabel(finding) << ": "
                    << core::severityName(finding.severity) << ": " << finding.code << ": " << finding.message
                    << lineEnd;
        if (directory && finding.counterexample)
            writeFailed |= !writeCounterexample(*finding.counterexample, finding, *directory, used, streams);
    }
    for (const std::string& abstraction : result.abstractions)
        streams.out << path << ": abstracted: " << abstraction << lineEnd;
    printPropertyVerdicts(path, result, streams.out);
    streams.out << path << ": ";
    if (loaded.model->templateKind() == core::TemplateKind::Gemma)
        streams.out << result.reachableSteps.size() << " reachable steps, ";
    streams.out << result.configurations << " reachable configurations, ";
    if (result.bothLayers && loaded.model->templateKind() == core::TemplateKind::Gemma)
        streams.out << result.programStates << " program states (both layers), ";
    streams.out << result.findings.size() << " finding(s)" << (result.exhaustive ? "" : " (not exhaustive)");
    if (!automatic.empty())
        streams.out << ", Complete automatic: " << joined(automatic);
    if (result.closedLoop)
        streams.out << ", closed loop";
    if (result.singleFaults)
        streams.out << ", single faults: " << result.faultChoices << " fault choices at every scan, "
                    << result.faultedStates << " faulted states";
    streams.out << lineEnd;
    if (writeFailed)
        return UnreadableInput; // the output is incomplete: that comes first
    if (result.violated())
        return ModelHasErrors;
    return result.undecided() ? Undecided : Success;
}

} // namespace cli
