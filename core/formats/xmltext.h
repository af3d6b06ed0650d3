#pragma once

// Making arbitrary user text fit for XML 1.0, which cannot carry control
// characters (other than tab, line feed, carriage return) nor invalid UTF-8,
// whatever the escaping; and checking that a text read back is well-formed
// XML 1.0 before an XML library sees it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace core {

// Valid UTF-8 with every character XML 1.0 allows; anything else (invalid
// bytes, control characters, U+FFFE, U+FFFF) becomes U+FFFD.
std::string xmlSafeText(std::string_view text);

// Like xmlSafeText, and tab, line feed and carriage return become spaces, as
// an XML reader would normalise them in an attribute anyway.
std::string xmlSafeAttribute(std::string_view text);

// tinyxml2 compares each attribute with every earlier one of its element, so
// an element with n attributes costs n^2: the cap keeps reading linear.
// PLCopen elements have at most about ten.
inline constexpr std::size_t kMaxXmlAttributesPerElement = 32;
// Below tinyxml2's own limit (100), so that the check reports it with a position.
inline constexpr std::size_t kMaxXmlDepth = 64;

struct XmlProblem {
    std::size_t offset = 0; // of the first byte of what is wrong
    std::string message;    // what is wrong, in English
};

struct XmlCheck {
    std::optional<XmlProblem> problem; // nullopt when the text is well-formed
    std::size_t rootOffset = 0;        // of the root element's '<' when well-formed
};

// One linear pass: UTF-8 made only of XML 1.0 characters (an optional byte
// order mark first), an optional XML declaration of version 1.0 in UTF-8,
// comments and processing instructions, exactly one root element, matching
// tags, quoted attributes with distinct names, character references to XML
// characters and only the five predefined entities. A DOCTYPE is refused: no
// entity is ever declared or expanded. Namespaces are not checked.
XmlCheck checkWellFormedXml(std::string_view text);

} // namespace core
