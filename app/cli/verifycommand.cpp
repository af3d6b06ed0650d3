#include "verifycommand.h"

#include "core/fileio.h"
#include "core/modelfiles.h"
#include "core/promela.h"
#include "core/verification.h"

#include <filesystem>
#include <ostream>
#include <set>
#include <system_error>

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

} // namespace

int commandVerify(const Arguments& args, Streams streams)
{
    if (args.positional().size() != 1) {
        streams.err << "ggstudio-cli: verify takes one model file\nTry 'ggstudio-cli --help'.\n";
        return UsageError;
    }
    const std::string& path = args.positional()[0];
    const std::optional<std::string> directory = args.value("--counterexamples");
    if (directory && directory->empty()) {
        streams.err << "ggstudio-cli: --counterexamples needs a directory\nTry 'ggstudio-cli --help'.\n";
        return UsageError;
    }
    core::LoadedModel loaded = core::loadModelFile(path);
    if (!loaded.ok()) {
        streams.err << loaded.error.toString() << "\n";
        return UnreadableInput;
    }
    if (directory) {
        std::error_code error;
        std::filesystem::create_directories(*directory, error);
        if (error) {
            streams.err << *directory << ": cannot create the directory: " << error.message() << "\n";
            return UnreadableInput;
        }
    }
    if (const std::optional<std::string> promela = args.value("--promela")) {
        if (promela->empty()) {
            streams.err << "ggstudio-cli: --promela needs an output file\nTry 'ggstudio-cli --help'.\n";
            return UsageError;
        }
        if (core::Status status = core::writeFileAtomically(*promela, core::exportPromela(*loaded.model)); !status) {
            streams.err << *promela << ": " << status.message << "\n";
            return UnreadableInput;
        }
    }
    const core::VerificationResult result = core::verifyModel(*loaded.model);
    std::set<std::string> used;
    for (const core::VerificationFinding& finding : result.findings) {
        streams.out << path << ": " << core::verificationElementLabel(finding) << ": "
                    << core::severityName(finding.severity) << ": " << finding.code << ": " << finding.message
                    << "\n";
        if (!directory || !finding.counterexample)
            continue;
        const std::string file =
            (std::filesystem::path(*directory) / counterexampleName(finding, used)).string();
        if (core::Status status = core::writeFileAtomically(file, finding.counterexample->text); !status) {
            streams.err << file << ": " << status.message << "\n";
            return UnreadableInput;
        }
        streams.out << "    counterexample: " << file << " (" << finding.counterexample->scans << " scans)\n";
    }
    streams.out << path << ": " << result.reachableSteps.size() << " reachable steps, " << result.configurations
                << " reachable configurations, " << result.findings.size() << " finding(s)"
                << (result.exhaustive ? "" : " (not exhaustive)") << "\n";
    return result.violated() ? ModelHasErrors : Success;
}

} // namespace cli
