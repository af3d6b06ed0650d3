#pragma once

// Making arbitrary user text fit for XML 1.0, which cannot carry control
// characters (other than tab, line feed, carriage return) nor invalid UTF-8,
// whatever the escaping.

#include <string>
#include <string_view>

namespace core {

// Valid UTF-8 with every character XML 1.0 allows; anything else (invalid
// bytes, control characters, U+FFFE, U+FFFF) becomes U+FFFD.
std::string xmlSafeText(std::string_view text);

// Like xmlSafeText, and tab, line feed and carriage return become spaces, as
// an XML reader would normalise them in an attribute anyway.
std::string xmlSafeAttribute(std::string_view text);

} // namespace core
