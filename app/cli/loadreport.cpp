#include "loadreport.h"

#include "terminal.h"

namespace cli {

void printLoadError(std::ostream& err, const core::LoadError& error)
{
    err << error.toStringWithoutAdvice();
    if (!error.advice.empty()) {
        err << "; ";
        writeVerbatim(err, error.advice);
    }
    err << lineEnd;
}

core::LoadedModel loadAndReport(const std::string& path, std::ostream& err, core::TemplateSupport support)
{
    core::LoadedModel loaded = core::loadSupportedModelFile(path, support);
    if (!loaded.ok()) {
        printLoadError(err, loaded.error);
        return loaded;
    }
    for (const core::LoadWarning& warning : loaded.warnings)
        err << warning.toString() << lineEnd;
    return loaded;
}

} // namespace cli
