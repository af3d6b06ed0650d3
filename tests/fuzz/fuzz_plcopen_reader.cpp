// libFuzzer target: the PLCopen XML reader on arbitrary bytes. Besides
// crashes, sanitizer reports and slow inputs (the well-formedness check must
// stay linear), it checks that tinyxml2 parses every text the check lets
// through, that every XML error has a line and column, and that whatever
// loads survives a PLCopen export and a re-read.

#include "core/model/model.h"
#include "core/formats/plcopenreader.h"
#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/xmltext.h"

#include <tinyxml2.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void expect(bool condition)
{
    if (!condition)
        std::abort();
}

void expectReExportReadsBack(const core::Model& model)
{
    core::PlcOpenOptions options;
    options.now = [] { return std::string("2026-12-02T10:00:00"); };
    const std::string xml = core::writePlcOpenXml(core::buildPlcProject(model, model.settings().dialect), model, options);
    expect(!core::checkWellFormedXml(xml).problem.has_value());
    auto reread = core::readPlcOpenModel(xml, "export.xml");
    const auto* again = std::get_if<std::unique_ptr<core::Model>>(&reread);
    expect(again != nullptr);
    expect((*again)->sameContent(model));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const core::XmlCheck check = core::checkWellFormedXml(text);
    if (check.problem) {
        expect(check.problem->offset <= text.size());
        expect(!check.problem->message.empty());
    } else {
        // The check must not let through what tinyxml2 cannot read.
        tinyxml2::XMLDocument document;
        expect(document.Parse(text.data(), text.size()) == tinyxml2::XML_SUCCESS);
        expect(document.RootElement() != nullptr);
    }

    auto result = core::readPlcOpenModel(text, "fuzz.xml");
    if (const auto* error = std::get_if<core::LoadError>(&result)) {
        expect(!error->message.empty());
        if (error->message.rfind("not well-formed XML: ", 0) == 0)
            expect(error->location.rfind("line ", 0) == 0 && error->location.find(", column ") != std::string::npos);
    } else {
        const core::Model& model = *std::get<std::unique_ptr<core::Model>>(result);
        expect(!check.problem.has_value());
        expect(model.invariantViolations().empty());
        expectReExportReadsBack(model);
    }
    return 0;
}
