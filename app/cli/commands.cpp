#include "commands.h"

#include "arguments.h"

#include "core/checks/checks.h"
#include "core/formats/fileio.h"
#include "core/formats/gggeneratorformat.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"
#include "core/codegen/plcopenwriter.h"
#include "core/machine/closedloopscenario.h"
#include "core/machine/machineloop.h"
#include "core/simulation/scenario.h"
#include "core/simulation/simulator.h"
#include "core/templates/packml/packmlmodel.h"
#include "core/templates/packml/packmlprogram.h"
#include "core/codegen/stexport.h"
#include "core/codegen/stgenerator.h"
#include "core/templates/gemma/gemmacodegen.h"
#include "cycletime.h"
#include "faultoption.h"
#include "loadreport.h"
#ifdef GGSTUDIO_HAVE_MODBUS
#include "modbussimulate.h"
#endif
#include "packmlsimulate.h"
#include "terminal.h"
#include "testcommand.h"
#include "verifycommand.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace cli {

namespace {

const char* const kUsage =
    "Usage: ggstudio-cli COMMAND [ARGUMENTS]\n"
    "\n"
    "Commands:\n"
    "  new OUT|- [--to native|gg-generator] [--template gemma|packml] [--edition 2015|2022]\n"
    "      Write a new model file: the GEMMA template (default), or a PackML model of the\n"
    "      edition (default 2015) with the base modes and a Cmd_ input per command.\n"
    "  validate FILE...\n"
    "      Check models; print FILE: ELEMENT: severity: CODE: message lines.\n"
    "      Exit 0 without errors, 1 when a model has errors, 2 when a file cannot be read.\n"
    "  convert IN OUT|- [--to native|gg-generator]\n"
    "      Convert between GG Studio JSON, GG-Generator JSON and (as input) GG Studio PLCopen XML.\n"
    "      A PackML model converts to GG Studio JSON only.\n"
    "  export MODEL -o OUT|- [--dialect iec|codesys] [--format plcopen|st|st-folder]\n"
    "         [--cycle-time 20ms] [--force]\n"
    "      Generate the PLC program: PLCopen XML (default for .xml), one IEC Structured Text\n"
    "      file (default for .st) or a folder with one .st file per POU. The dialect and\n"
    "      cycle time default to the model's settings. A model with errors is refused\n"
    "      unless --force (the code then carries a comment at each problem). PackML models too.\n"
    "  st MODEL [--dialect iec|codesys] [--step STEP]\n"
    "      Print the GEMMA program's Structured Text, or with --step the function block of\n"
    "      one visible macro-step or enclosing step (its nested GRAFCET). A PackML model:\n"
    "      its PROGRAM, or with --step the function block of an instance (Production_Execute).\n"
    "  simulate MODEL [SCENARIO] [--scans N] [--trace] [--explain] [--open-loop]\n"
    "           [--fault \"SCAN:SENSOR stuck TRUE|FALSE|flicker|clear\"] [--fault \"SCAN:COMPONENT jam\"]\n"
    "      Run the GEMMA program scan by scan: one line 'scan N: STEP [fired TRANSITION]' per\n"
    "      scan (--trace adds inputs, Entry, tokens, Complete, the active steps, timers and\n"
    "      Unstable of each nested GRAFCET and the outputs they drive; --explain ends with why\n"
    "      each transition of the active step and of its GRAFCET fires or not in the next scan).\n"
    "      A model with a machine runs in closed loop: the machine sets its sensors after\n"
    "      each scan (--trace shows them), the scenario plays the operator; --open-loop\n"
    "      ignores the machine. Each --fault (repeatable) injects a fault before scan SCAN, as a\n"
    "      scenario's 'at SCAN: fault ...' line; the output says when it begins.\n"
    "      Runs the scenario's last scan, else 10 scans, or N (at most 10000000, as a scenario).\n"
    "      Exit 1 when an expectation of the scenario fails.\n"
    "  test MODEL SCENARIO|FOLDER... [--junit FILE]\n"
    "  test --models MODEL|FOLDER [--models ...] SCENARIO|FOLDER... [--junit FILE]\n"
    "      Run each scenario (a FOLDER: its *.scenario files) against each model, in closed loop\n"
    "      when the model has a machine; print one line per scenario (PASS or FAIL, the scans run,\n"
    "      the first failed expectation with its scan, expected and seen) and write JUnit XML\n"
    "      with --junit (one testsuite per model). --models takes a model or a folder of\n"
    "      models (*.json, *.xml): a class's models against one suite.\n"
    "      Exit 0 when every scenario passes, 1 when one fails, 2 when a file cannot be read.\n"
    "  verify MODEL [--counterexamples DIR] [--promela OUT.pml]\n"
    "         [--complete-automatic STEP[,STEP...]|all] [--property \"never P\"]... [--exact-time]\n"
    "         [--time-limit 4s] [--machine [--faults single]]\n"
    "      Prove properties of both layers (docs/verification.md): print FILE: ELEMENTS:\n"
    "      severity: CODE: message lines; with DIR, write each counterexample as a scenario\n"
    "      file there; with --promela, also write the model for SPIN. The model's own\n"
    "      properties are checked, and each --property (never P or always P) with them.\n"
    "      Timers may or may not have elapsed unless --exact-time counts time in scans.\n"
    "      Complete of a nested step without GRAFCET is free (any value at any scan) unless\n"
    "      named by --complete-automatic (TRUE at every scan, as the skeleton FB).\n"
    "      The whole run stops after --time-limit (default 4s, at most 1h; what it could not\n"
    "      decide by then is reported as not exhaustive or undecided).\n"
    "      --machine explores the program with the model's machine (closed loop): the inputs\n"
    "      its sensors drive follow the machine, operator inputs stay free, time is counted in\n"
    "      scans; counterexamples replay with the machine (simulate); --promela writes it too.\n"
    "      --faults single adds, at any scan, any one sensor stuck TRUE, stuck FALSE or\n"
    "      flickering, or one cylinder or conveyor jammed; properties may read faulted and\n"
    "      T/faulted (a fault in effect, for at least T); counterexamples carry the fault.\n"
    "      Each property ends as holds, violated or undecided. Exit 1 when a finding is an\n"
    "      error or a warning (a property violated), else 3 when something is undecided (a\n"
    "      property, or a claim whose run does not replay); 2 when a file cannot be written.\n"
    "      A PackML model: GV130-GV138 (docs/packml.md); --promela writes its program with\n"
    "      time counted in scans; --complete-automatic is for GEMMA models.\n"
    "\n"
    "Formats: IN is recognised by its content. OUT is GG-Generator JSON when it ends in\n"
    ".gg.json, GG Studio JSON otherwise; --to overrides the extension. OUT - is standard\n"
    "output (export -o - needs --format plcopen or st). A file is only ever replaced when\n"
    "it is a regular file: never a FIFO, a device or a socket (exit 2).\n"
    "\n"
    "Options:\n"
    "  --help       Show this help.\n"
    "  --version    Show the version.\n";

bool endsWith(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Output format from --to, else from the file name.
bool outputFormat(const Arguments& args, const std::string& path, core::ModelFormat& format, std::ostream& err)
{
    if (auto to = args.value("--to")) {
        if (*to == "native") {
            format = core::ModelFormat::Native;
        } else if (*to == "gg-generator") {
            format = core::ModelFormat::GGGenerator;
        } else {
            err << "ggstudio-cli: --to takes native or gg-generator, not '" << *to << "'" << lineEnd;
            return false;
        }
        return true;
    }
    format = endsWith(path, ".gg.json") ? core::ModelFormat::GGGenerator : core::ModelFormat::Native;
    return true;
}

int usageError(std::ostream& err, const std::string& message)
{
    err << "ggstudio-cli: " << message << lineEnd << "Try 'ggstudio-cli --help'." << lineEnd;
    return UsageError;
}

// "-" where a command writes one file is standard output.
bool isStandardOutput(const std::string& path)
{
    return path == "-";
}

int save(const core::Model& model, const std::string& path, core::ModelFormat format, Streams streams)
{
    if (format == core::ModelFormat::GGGenerator && model.templateKind() != core::TemplateKind::Gemma) {
        streams.err << "ggstudio-cli: GG-Generator JSON holds GEMMA models only; write a PackML model as a GG "
                       "Studio model file (--to native)"
                    << lineEnd;
        return UsageError;
    }
    if (format == core::ModelFormat::GGGenerator) {
        for (const core::GGGeneratorLoss& loss : core::ggGeneratorLosses(model))
            streams.err << "ggstudio-cli: warning: " << core::toText(loss) << lineEnd;
    }
    if (isStandardOutput(path)) {
        writeVerbatim(streams.out, format == core::ModelFormat::GGGenerator ? core::saveGGGeneratorJson(model)
                                                                            : core::saveNativeJson(model));
        return Success;
    }
    core::Status status = core::saveModelFile(model, path, format);
    if (!status) {
        streams.err << path << ": " << status.message << lineEnd;
        return UnreadableInput;
    }
    return Success;
}

std::unique_ptr<core::Model> loadOrReport(const std::string& path, std::ostream& err,
                                          core::TemplateSupport support = core::TemplateSupport::GemmaOnly)
{
    return std::move(loadAndReport(path, err, support).model);
}

// The model `new` writes, from --template and --edition; nullptr after a
// usage error.
std::unique_ptr<core::Model> newModel(const Arguments& args, std::ostream& err)
{
    const std::string templateName = args.value("--template").value_or("gemma");
    const std::optional<std::string> editionName = args.value("--edition");
    if (templateName == "gemma") {
        if (editionName) {
            usageError(err, "--edition is for PackML models (--template packml)");
            return nullptr;
        }
        return std::make_unique<core::Model>();
    }
    if (templateName != "packml") {
        usageError(err, "--template takes gemma or packml, not '" + templateName + "'");
        return nullptr;
    }
    const std::optional<core::packml::Edition> edition = core::packml::parseEdition(editionName.value_or("2015"));
    if (!edition) {
        usageError(err, "--edition takes 2015 or 2022, not '" + *editionName + "'");
        return nullptr;
    }
    return std::make_unique<core::Model>(core::packml::newModel(*edition));
}

int commandNew(const Arguments& args, Streams streams)
{
    if (args.positional().size() != 1)
        return usageError(streams.err, "new takes one output file");
    const std::string& path = args.positional()[0];
    core::ModelFormat format;
    if (!outputFormat(args, path, format, streams.err))
        return UsageError;
    const std::unique_ptr<core::Model> model = newModel(args, streams.err);
    if (!model)
        return UsageError;
    return save(*model, path, format, streams);
}

int validateOne(const std::string& path, Streams streams)
{
    core::LoadedModel loaded = loadAndReport(path, streams.err, core::TemplateSupport::GemmaAndPackML);
    if (!loaded.ok())
        return UnreadableInput;
    const std::vector<core::Diagnostic> diagnostics = core::checkModel(*loaded.model);
    for (const core::Diagnostic& d : diagnostics) {
        streams.out << path << ": " << core::diagnosticElementLabel(d) << ": " << core::severityName(d.severity)
                    << ": " << d.code << ": " << d.message << lineEnd;
    }
    return core::hasErrors(diagnostics) ? ModelHasErrors : Success;
}

int commandValidate(const Arguments& args, Streams streams)
{
    if (args.positional().empty())
        return usageError(streams.err, "validate takes at least one model file");
    int worst = Success;
    for (const std::string& path : args.positional())
        worst = std::max(worst, validateOne(path, streams));
    return worst;
}

int commandConvert(const Arguments& args, Streams streams)
{
    if (args.positional().size() != 2)
        return usageError(streams.err, "convert takes an input and an output file");
    const std::string& input = args.positional()[0];
    const std::string& output = args.positional()[1];
    core::ModelFormat format;
    if (!outputFormat(args, output, format, streams.err))
        return UsageError;
    std::unique_ptr<core::Model> model = loadOrReport(input, streams.err, core::TemplateSupport::GemmaAndPackML);
    if (!model)
        return UnreadableInput;
    return save(*model, output, format, streams);
}

// The dialect from --dialect, else the model's setting.
bool chooseDialect(const Arguments& args, const core::Model& model, core::Dialect& dialect, std::ostream& err)
{
    dialect = model.settings().dialect;
    if (auto given = args.value("--dialect"); given && !core::parseDialect(*given, dialect)) {
        err << "ggstudio-cli: --dialect takes iec or codesys, not '" << *given << "'" << lineEnd;
        return false;
    }
    return true;
}

enum class ExportFormat { PlcOpen, StFile, StFolder };

bool chooseExportFormat(const Arguments& args, const std::string& output, ExportFormat& format, std::ostream& err)
{
    std::string name = args.value("--format").value_or("");
    if (name.empty()) {
        if (isStandardOutput(output)) {
            err << "ggstudio-cli: -o - writes to standard output: say what with --format plcopen or st" << lineEnd;
            return false;
        } else if (endsWith(output, ".xml")) {
            name = "plcopen";
        } else if (endsWith(output, ".st")) {
            name = "st";
        } else {
            err << "ggstudio-cli: cannot tell the export format from '" << output
                << "': use --format plcopen, st or st-folder" << lineEnd;
            return false;
        }
    }
    static const std::map<std::string, ExportFormat> formats{
        {"plcopen", ExportFormat::PlcOpen}, {"st", ExportFormat::StFile}, {"st-folder", ExportFormat::StFolder}};
    auto found = formats.find(name);
    if (found == formats.end()) {
        err << "ggstudio-cli: --format takes plcopen, st or st-folder, not '" << name << "'" << lineEnd;
        return false;
    }
    format = found->second;
    return true;
}

// Lists the errors of a model about to be exported; true when there are none.
bool reportExportErrors(const std::string& path, const core::Model& model, bool force, std::ostream& err)
{
    const std::vector<core::Diagnostic> diagnostics = core::checkModel(model);
    if (!core::hasErrors(diagnostics))
        return true;
    for (const core::Diagnostic& d : diagnostics) {
        if (d.severity == core::Severity::Error)
            err << path << ": " << core::diagnosticElementLabel(d) << ": error: " << d.code << ": " << d.message
                << lineEnd;
    }
    err << (force ? "ggstudio-cli: exporting anyway (--force): the code marks each problem with a comment"
                  : "ggstudio-cli: the model has errors; fix them or export anyway with --force")
        << lineEnd;
    return force;
}

// The one file of a PLCopen or single-file export, for standard output.
std::string exportText(const core::Model& model, core::Dialect dialect, ExportFormat format)
{
    if (format == ExportFormat::PlcOpen)
        return core::writePlcOpenXml(core::buildPlcProject(model, dialect), model);
    // Always IEC, as core::exportStSingleFile writes it.
    return core::formatSingleFileIec(core::buildPlcProject(model, core::Dialect::Iec));
}

core::Status writeExport(const core::Model& model, core::Dialect dialect, ExportFormat format,
                         const std::string& output)
{
    switch (format) {
    case ExportFormat::PlcOpen:
        return core::writeFileAtomically(output, core::writePlcOpenXml(core::buildPlcProject(model, dialect), model));
    case ExportFormat::StFile:
        return core::exportStSingleFile(model, output);
    case ExportFormat::StFolder:
        return core::exportStFolder(core::buildPlcProject(model, dialect), output);
    }
    return core::Status::failure("export", "unknown export format");
}

int commandExport(const Arguments& args, Streams streams)
{
    if (args.positional().size() != 1)
        return usageError(streams.err, "export takes one model file");
    const std::string& input = args.positional()[0];
    const std::optional<std::string> output = args.value("--output");
    if (!output || output->empty())
        return usageError(streams.err, "export needs an output: -o OUT");
    ExportFormat format;
    if (!chooseExportFormat(args, *output, format, streams.err))
        return UsageError;
    if (format == ExportFormat::StFolder && isStandardOutput(*output))
        return usageError(streams.err, "--format st-folder writes a folder: it cannot go to standard output");

    std::unique_ptr<core::Model> model = loadOrReport(input, streams.err, core::TemplateSupport::GemmaAndPackML);
    if (!model)
        return UnreadableInput;
    core::Dialect dialect;
    if (!chooseDialect(args, *model, dialect, streams.err))
        return UsageError;
    if (format == ExportFormat::StFile && dialect == core::Dialect::Codesys && args.has("--dialect"))
        return usageError(streams.err, "--format st writes one IEC file: CODESYS has no single-file form; "
                                       "use --format st-folder or plcopen");
    if (auto cycle = args.value("--cycle-time")) {
        const std::optional<int> milliseconds = parseCycleTime(*cycle);
        if (!milliseconds)
            return usageError(streams.err, "--cycle-time takes a duration such as 20ms, 1s or T#1s500ms, not '" +
                                               *cycle + "'");
        if (core::Status status = model->setCycleTimeMs(*milliseconds); !status)
            return usageError(streams.err, status.message);
    }
    if (!reportExportErrors(input, *model, args.has("--force"), streams.err))
        return ModelHasErrors;
    if (isStandardOutput(*output)) {
        writeVerbatim(streams.out, exportText(*model, dialect, format));
        return Success;
    }
    if (core::Status status = writeExport(*model, dialect, format, *output); !status) {
        streams.err << *output << ": " << status.message << lineEnd;
        return UnreadableInput;
    }
    return Success;
}

// The function block of one visible macro-step or enclosing step.
int printFunctionBlock(const core::Model& model, const std::string& stepId, core::Dialect dialect, Streams streams)
{
    const core::Step* step = model.step(stepId);
    if (!step)
        return usageError(streams.err, "--step: there is no step '" + stepId + "' in the GEMMA template");
    if (step->hidden || step->type == core::StepType::Simple)
        return usageError(streams.err, "--step: " + step->id + " has no function block (only visible macro-steps "
                                                               "and enclosing steps have one)");
    const core::PlcProject project = core::buildPlcProject(model, dialect);
    const std::string name = step->id + "_FB";
    for (const core::PlcPou& pou : project.pous) {
        if (pou.name == name) {
            writeVerbatim(streams.out, core::formatPou(pou, dialect));
            return Success;
        }
    }
    return usageError(streams.err, "--step: no function block " + name + " was generated");
}

// A PackML model: the PROGRAM, or with --step the function block an
// instance <Mode>_<State> runs (its mode's GRAFCET, the one it is the same
// as, or the skeleton).
int printPackmlPou(const core::Model& model, const std::optional<std::string>& instanceName, core::Dialect dialect,
                   Streams streams)
{
    const core::PlcProject project = core::buildPlcProject(model, dialect);
    if (!instanceName) {
        writeVerbatim(streams.out, core::formatPou(project.pous.back(), dialect));
        return Success;
    }
    const core::packml::PackmlProgram program = core::packml::buildPackmlProgram(model);
    const auto instance = std::find_if(program.instances.begin(), program.instances.end(),
                                       [&](const core::packml::ProgramInstance& candidate) {
                                           return core::equalsIgnoreCase(candidate.name, *instanceName);
                                       });
    if (instance == program.instances.end())
        return usageError(streams.err, "--step: there is no instance '" + *instanceName
                                           + "' in this PackML model: name a mode and an enabled acting state or "
                                             "Execute, such as Production_Execute");
    for (const core::PlcPou& pou : project.pous) {
        if (pou.name == instance->typeName) {
            writeVerbatim(streams.out, core::formatPou(pou, dialect));
            return Success;
        }
    }
    return usageError(streams.err, "--step: no function block " + instance->typeName + " was generated");
}

int commandSt(const Arguments& args, Streams streams)
{
    if (args.positional().size() != 1)
        return usageError(streams.err, "st takes one model file");
    std::unique_ptr<core::Model> model =
        loadOrReport(args.positional()[0], streams.err, core::TemplateSupport::GemmaAndPackML);
    if (!model)
        return UnreadableInput;
    core::Dialect dialect;
    if (!chooseDialect(args, *model, dialect, streams.err))
        return UsageError;
    const std::optional<std::string> stepId = args.value("--step");
    if (model->packml())
        return printPackmlPou(*model, stepId, dialect, streams);
    if (!stepId) {
        writeVerbatim(streams.out, core::previewGemmaProgram(*model, dialect).text);
        return Success;
    }
    return printFunctionBlock(*model, *stepId, dialect, streams);
}

// --- simulate ----------------------------------------------------------------

constexpr std::int64_t kDefaultSimulationScans = 10;

std::string joinValues(const std::vector<std::string>& names, const std::vector<bool>& values)
{
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
        text += (i ? ", " : "") + names[i] + " = " + (values[i] ? "TRUE" : "FALSE");
    return text.empty() ? "none" : text;
}

// The active steps, timers and Unstable of every nested GRAFCET, then the
// outputs they drive.
void printNestedState(const core::ScanRecord& record, const core::Simulator& simulator, std::ostream& out)
{
    const std::vector<std::string>& nested = simulator.nestedSteps();
    std::vector<std::string> outputs;
    for (std::size_t i = 0; i < nested.size() && i < record.nestedActive.size(); ++i) {
        if (!simulator.hasGrafcet(nested[i]))
            continue;
        std::string steps;
        for (int number : record.nestedActive[i])
            steps += (steps.empty() ? "" : ", ") + std::to_string(number);
        out << "    " << nested[i] << " steps: " << (steps.empty() ? "none" : steps) << lineEnd;
        for (const std::string& name : simulator.nestedOutputs(nested[i])) {
            if (std::find(outputs.begin(), outputs.end(), name) == outputs.end())
                outputs.push_back(name);
        }
        const core::NestedEngine* engine = simulator.grafcetEngine(nested[i]);
        std::string timers;
        for (const core::NestedTimerState& timer : engine->timers())
            timers += (timers.empty() ? "" : ", ") + timer.name + " = " + std::to_string(timer.elapsedMs) + " of "
                    + std::to_string(timer.durationMs) + " ms";
        if (!timers.empty())
            out << "    " << nested[i] << " timers: " << timers << lineEnd;
        if (i < record.unstable.size() && record.unstable[i])
            out << "    " << nested[i] << " Unstable = TRUE" << lineEnd;
    }
    if (outputs.empty())
        return;
    std::string values;
    for (const std::string& name : outputs)
        values += (values.empty() ? "" : ", ") + name + " = " + core::cond::formatValue(simulator.variable(name));
    out << "    outputs: " << values << lineEnd;
}

void printScan(const core::ScanRecord& record, const core::Simulator& simulator, bool trace, std::ostream& out)
{
    out << "scan " << record.scan << ": " << (record.stepAfter.empty() ? "(no visible step)" : record.stepAfter);
    if (!record.fired.empty())
        out << " fired " << record.fired;
    out << lineEnd;
    if (!trace)
        return;
    std::string inputs;
    for (const core::InputChange& change : record.changedInputs)
        inputs += (inputs.empty() ? "" : ", ") + change.variable + " = " + core::cond::formatValue(change.value);
    out << "    inputs changed: " << (inputs.empty() ? "none" : inputs) << lineEnd;
    out << "    Entry = " << (record.entry ? "TRUE" : "FALSE") << lineEnd;
    out << "    tokens: " << joinValues(simulator.tokenNames(), record.tokens) << lineEnd;
    out << "    Complete: " << joinValues(simulator.nestedSteps(), record.complete) << lineEnd;
    printNestedState(record, simulator, out);
}

std::string stepNumbers(const std::vector<int>& numbers)
{
    std::string text;
    for (int number : numbers)
        text += (text.empty() ? "" : ", ") + std::to_string(number);
    return text.empty() ? "none" : text;
}

std::string reasonsText(const std::vector<core::ExplanationReason>& reasons)
{
    std::string text;
    for (const core::ExplanationReason& reason : reasons)
        text += (text.empty() ? ": " : "; ") + core::toText(reason);
    return text;
}

// Why each transition of the active step, and of its nested GRAFCET, fires
// or not in the next scan.
void printExplanation(const core::Simulator& simulator, std::ostream& out)
{
    const std::string step = simulator.activeStepId();
    out << "next scan " << simulator.scanCount() + 1 << ": "
        << (step.empty() ? std::string("(no visible step)") : step) << lineEnd;
    for (const core::TransitionExplanation& e : simulator.explain())
        out << "    " << e.transitionId << ": " << core::transitionStatusName(e.status) << reasonsText(e.reasons)
            << lineEnd;
    if (!simulator.hasGrafcet(step))
        return;
    const core::NestedExplanation nested = simulator.explainNested(step);
    out << "    " << step << " GRAFCET, steps " << stepNumbers(nested.situation);
    if (nested.initialization)
        out << " (re-initialised first)";
    if (nested.untilStable)
        out << ", first evolution";
    out << ":" << lineEnd;
    for (const core::NestedTransitionExplanation& t : nested.transitions)
        out << "        T" << t.number << " (" << stepNumbers(t.upstream) << " -> " << stepNumbers(t.downstream)
            << "): " << core::nestedTransitionStatusName(t.status) << reasonsText(t.reasons) << lineEnd;
}

// The sensors the machine set after a scan, read by the next one.
void printMachineSensors(const core::machine::MachineLoop& loop, std::ostream& out)
{
    std::string sensors;
    for (const core::InputChange& change : loop.lastSensorChanges())
        sensors += (sensors.empty() ? "" : ", ") + change.variable + " = " + core::cond::formatValue(change.value);
    if (!sensors.empty())
        out << "    machine set: " << sensors << lineEnd;
}

// The scenario file, parsed and checked against the model (in closed loop,
// against the machine too); false (and the errors printed) when it cannot be used.
bool loadScenario(const std::string& path, const core::Simulator& simulator, const core::machine::MachineLoop* loop,
                  core::Scenario& scenario, std::ostream& err)
{
    std::string text;
    if (core::Status status = core::readFileLimited(path, 16u * 1024u * 1024u, text); !status) {
        err << path << ": " << status.message << lineEnd;
        return false;
    }
    core::ScenarioParseResult parsed = core::parseScenario(text, path);
    std::vector<core::ScenarioError> errors = parsed.errors;
    if (parsed.ok())
        errors = core::validateScenario(parsed.scenario, simulator,
                                        loop ? core::FaultLines::CheckedByMachine : core::FaultLines::Refused);
    if (errors.empty() && loop)
        errors = core::machine::validateClosedLoopScenario(parsed.scenario, *loop);
    for (const core::ScenarioError& error : errors)
        err << error.toString() << lineEnd;
    scenario = std::move(parsed.scenario);
    return errors.empty();
}

int commandSimulate(const Arguments& args, Streams streams)
{
    const std::vector<std::string>& files = args.positional();
    if (files.empty() || files.size() > 2)
        return usageError(streams.err, "simulate takes a model file and an optional scenario file");
    std::int64_t scans = 0;
    if (auto given = args.value("--scans")) {
        std::size_t used = 0;
        try {
            scans = std::stoll(*given, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != given->size() || scans < 1)
            return usageError(streams.err, "--scans takes a positive number of scans, not '" + *given + "'");
        if (scans > core::kMaxScenarioScan)
            return usageError(streams.err, "--scans takes at most " + std::to_string(core::kMaxScenarioScan)
                                               + " scans, not " + *given);
    }
    const std::vector<std::string> faultOptions = args.values("--fault");
    std::vector<core::ScenarioAction> faults;
    if (std::string error; !parseFaultOptions(faultOptions, faults, error))
        return usageError(streams.err, error);
    std::unique_ptr<core::Model> model = loadOrReport(files[0], streams.err, core::TemplateSupport::GemmaAndPackML);
    if (!model)
        return UnreadableInput;
    if (args.has("--modbus-server") || args.has("--modbus-client") || args.has("--print-modbus-map")
        || args.has("--modbus-map") || args.has("--unit-id")) {
        if (model->templateKind() == core::TemplateKind::PackML)
            return usageError(streams.err, "the Modbus link is for GEMMA models; PackML models are not linked yet");
        if (files.size() == 2)
            return usageError(streams.err, "a scenario cannot be played while linked over Modbus: the twin plays the inputs");
        if (!faults.empty() || args.has("--explain") || args.has("--trace"))
            return usageError(streams.err, "--fault, --trace and --explain are not available with the Modbus link");
#ifdef GGSTUDIO_HAVE_MODBUS
        return simulateModbus(args, files[0], *model, scans, streams);
#else
        return usageError(streams.err, "this ggstudio-cli was built without Qt SerialBus: the Modbus link is not available");
#endif
    }
    if (model->templateKind() == core::TemplateKind::PackML) {
        if (args.has("--explain"))
            return usageError(streams.err, "--explain is not available for PackML models yet");
        if (!faults.empty())
            return usageError(streams.err, "--fault needs the virtual machine of a GEMMA model");
        return simulatePackml(*model, files, scans, args.has("--trace"), streams);
    }
    core::Simulator simulator(*model);
    int errors = 0;
    for (const core::ProgramProblem& problem : simulator.program().problems)
        errors += problem.kind == core::ProgramProblem::Kind::Error ? 1 : 0;
    if (errors > 0)
        streams.err << files[0] << ": " << errors << " error(s) in the model (see 'ggstudio-cli validate'): "
                    << "a condition that cannot be used never fires, as in the generated code" << lineEnd;

    std::optional<core::machine::MachineLoop> loop;
    if (!model->machine().empty() && !args.has("--open-loop"))
        loop.emplace(simulator, model->machine());

    const bool openLoop = args.has("--open-loop");
    if (std::string error; !checkFaultOptions(faultOptions, faults, loop ? &*loop : nullptr, openLoop, error))
        return usageError(streams.err, error);
    core::Scenario scenario;
    if (files.size() == 2 && !loadScenario(files[1], simulator, loop ? &*loop : nullptr, scenario, streams.err))
        return UnreadableInput;
    // The options' faults join the scenario's; the default run reaches them.
    scenario.actions.insert(scenario.actions.end(), faults.begin(), faults.end());
    if (scans == 0)
        scans = scenario.lastScan() > 0 ? scenario.lastScan() : kDefaultSimulationScans;

    const bool trace = args.has("--trace");
    const FaultAnnouncements announcements(scenario);
    core::ScenarioRunner runner =
        loop ? core::ScenarioRunner(scenario, *loop) : core::ScenarioRunner(scenario, simulator);
    std::size_t failures = 0;
    for (std::int64_t i = 0; i < scans; ++i) {
        announcements.print(simulator.scanCount() + 1, streams.out);
        const core::ScanRecord record = runner.step();
        if (const auto& fault = simulator.fault()) {
            streams.err << files[0] << ": " << core::toText(*fault) << lineEnd;
            return RunTimeFault;
        }
        printScan(record, simulator, trace, streams.out);
        if (trace && loop)
            printMachineSensors(*loop, streams.out);
        for (const core::ScenarioFailure& failure : runner.lastFailures())
            streams.err << files[1] << ":" << failure.line << ": " << core::toText(failure) << lineEnd;
        failures += runner.lastFailures().size();
    }
    if (args.has("--explain"))
        printExplanation(simulator, streams.out);
    if (files.size() == 2) {
        std::size_t expectations = 0;
        for (const core::ScenarioAction& action : scenario.actions)
            expectations += action.isExpectation() && action.scan <= scans ? 1 : 0;
        if (failures > 0) {
            streams.err << files[1] << ": " << failures << " of " << expectations << " expectation(s) failed"
                        << lineEnd;
            return ModelHasErrors;
        }
        streams.out << files[1] << ": all " << expectations << " expectation(s) met" << lineEnd;
    }
    return Success;
}

struct Command {
    std::function<int(const Arguments&, Streams)> run;
    std::vector<std::string> options;
    std::vector<std::string> flags;
};

const std::map<std::string, Command>& commands()
{
    static const std::map<std::string, Command> table{
        {"new", {commandNew, {"--to", "--template", "--edition"}, {}}},
        {"validate", {commandValidate, {}, {}}},
        {"convert", {commandConvert, {"--to"}, {}}},
        {"export", {commandExport, {"--output", "--dialect", "--format", "--cycle-time"}, {"--force"}}},
        {"st", {commandSt, {"--dialect", "--step"}, {}}},
        {"simulate", {commandSimulate, {"--scans", "--fault", "--modbus-server", "--modbus-client", "--modbus-map", "--unit-id"},
                      {"--trace", "--explain", "--open-loop", "--print-modbus-map"}}},
        {"test", {commandTest, {"--junit", "--models"}, {}}},
        {"verify", {commandVerify, {"--counterexamples", "--promela", "--complete-automatic", "--property", "--time-limit",
                     "--faults"},
                    {"--exact-time", "--machine"}}},
    };
    return table;
}

int runCommand(const std::vector<std::string>& words, Streams streams)
{
    if (words.empty())
        return usageError(streams.err, "no command given");
    const std::string& name = words.front();
    if (name == "--help" || name == "-h" || name == "help") {
        writeVerbatim(streams.out, kUsage);
        return Success;
    }
    if (name == "--version") {
        streams.out << "ggstudio-cli " << GGSTUDIO_VERSION << lineEnd;
        return Success;
    }
    auto command = commands().find(name);
    if (command == commands().end())
        return usageError(streams.err, "unknown command '" + name + "'");

    const std::vector<std::string> rest(words.begin() + 1, words.end());
    if (std::find(rest.begin(), rest.end(), "--help") != rest.end()) {
        writeVerbatim(streams.out, kUsage);
        return Success;
    }
    Arguments args(rest, command->second.flags);
    if (!args.error().empty())
        return usageError(streams.err, args.error());
    std::vector<std::string> allowed = command->second.options;
    allowed.insert(allowed.end(), command->second.flags.begin(), command->second.flags.end());
    if (std::string unknown = args.unknownOptions(allowed); !unknown.empty())
        return usageError(streams.err, unknown);
    return command->second.run(args, streams);
}

} // namespace

// Every message passes through a TerminalStream: user text quoted in it is
// escaped, whichever command prints it.
int run(const std::vector<std::string>& words, Streams streams)
{
    TerminalStream out(streams.out);
    TerminalStream err(streams.err);
    return runCommand(words, {out, err});
}

} // namespace cli
