#pragma once

// PLCopen XML export of the generated program (spec §7). The IEC dialect
// writes TC6 XML v2.01 (validates against tc6_xml_v201.xsd); the CODESYS
// dialect follows what CODESYS V3.5 exports (tc6_0200, GVL with the
// qualified_only attribute). Both carry the native model in the project's
// addData so that GG Studio can open the file again (core/formats/plcopenreader.h).

#include "core/model/model.h"
#include "core/codegen/plcproject.h"

#include <functional>
#include <string>
#include <string_view>

namespace core {

// The addData entry that carries the native model JSON. A URN, so that it
// looks like no real web address.
inline constexpr std::string_view kPlcOpenModelDataName = "urn:ggstudio:model:1";
inline constexpr std::string_view kPlcOpenModelElement = "ggstudio:model";

inline constexpr std::string_view kPlcOpenNamespace201 = "http://www.plcopen.org/xml/tc6_0201";
inline constexpr std::string_view kPlcOpenNamespace200 = "http://www.plcopen.org/xml/tc6_0200";
inline constexpr std::string_view kXhtmlNamespace = "http://www.w3.org/1999/xhtml";

// The current UTC time as an xs:dateTime without fraction: "2026-11-21T10:00:00".
std::string currentUtcDateTime();

struct PlcOpenOptions {
    // Injectable clock: the same model and the same clock give the same bytes.
    std::function<std::string()> now = currentUtcDateTime;
    std::string productVersion = GGSTUDIO_VERSION;
};

// The whole PLCopen XML document (UTF-8, with declaration), in the dialect of
// the project. User text is escaped or put in CDATA; in the code and the
// documentation, characters XML 1.0 cannot carry are replaced by U+FFFD,
// while the embedded model keeps them as JSON escapes (\u0001, \ufffe), so
// that it comes back exactly.
std::string writePlcOpenXml(const PlcProject& project, const Model& model, const PlcOpenOptions& options = {});

// The text of a <documentation> element for a comment: "(*" and "*)" are
// split ("( *", "* )"), since tools may turn documentation into an ST comment.
std::string plcOpenDocumentationText(std::string_view text);

// "T#20ms" (IEC task interval) and "PT0.02S" (CODESYS export style).
std::string iecTaskInterval(int cycleTimeMs);
std::string isoTaskInterval(int cycleTimeMs);

} // namespace core
