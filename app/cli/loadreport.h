#pragma once

// Loading a model file the way every command does: the error on failure, the
// warnings (what the model did not take over from the file) on success, both
// on the error stream, so that nothing is lost without a word.

#include "core/formats/modelfiles.h"

#include <ostream>
#include <string>

namespace cli {

core::LoadedModel loadAndReport(const std::string& path, std::ostream& err,
                                core::TemplateSupport support = core::TemplateSupport::GemmaOnly);

// "FILE: LOCATION: MESSAGE; ADVICE": the advice is fixed text and printed as
// it is, since the escaping of user text would double its backslashes
// ("write it as \u0000").
void printLoadError(std::ostream& err, const core::LoadError& error);

} // namespace cli
