#pragma once

// Where an element of a parsed document starts in its text: tinyxml2 keeps
// only the line, while messages give the line and the column.

#include <string>
#include <string_view>

namespace tinyxml2 {
class XMLElement;
}

namespace core {

// "line 12, column 5" for the '<' of the element's start tag; "line 12" when
// the tag cannot be found on its line (text that is not the element's document).
std::string describeElementPosition(std::string_view xmlText, const tinyxml2::XMLElement& element);

} // namespace core
