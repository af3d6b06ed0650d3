#include "core/formats/xmlelementposition.h"

#include "core/formats/fileio.h"

#include <tinyxml2.h>

#include <optional>

namespace core {

namespace {

using tinyxml2::XMLElement;

// How many elements of the same name start on the element's line before it,
// in document order: the element is the next start tag of that name there.
std::size_t sameNameBeforeOnLine(const XMLElement& target)
{
    std::size_t count = 0;
    bool found = false;
    const std::string_view name = target.Name();
    const int line = target.GetLineNum();
    // Iterative pre-order walk: the depth is bounded by the well-formedness
    // check, but a walk without recursion needs no such argument.
    const tinyxml2::XMLNode* node = target.GetDocument()->FirstChildElement();
    while (node && !found) {
        if (const XMLElement* element = node->ToElement()) {
            if (element == &target)
                found = true;
            else if (element->GetLineNum() == line && name == element->Name())
                ++count;
        }
        if (node->FirstChildElement()) {
            node = node->FirstChildElement();
            continue;
        }
        while (node && !node->NextSiblingElement())
            node = node->Parent();
        if (node)
            node = node->NextSiblingElement();
    }
    return count;
}

std::optional<std::size_t> lineStart(std::string_view text, int line)
{
    std::size_t offset = 0;
    for (int current = 1; current < line; ++current) {
        offset = text.find('\n', offset);
        if (offset == std::string_view::npos)
            return std::nullopt;
        ++offset;
    }
    return offset;
}

bool endsName(std::string_view text, std::size_t offset)
{
    if (offset >= text.size())
        return false;
    const char c = text[offset];
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '/' || c == '>';
}

} // namespace

std::string describeElementPosition(std::string_view xmlText, const XMLElement& element)
{
    const int line = element.GetLineNum();
    const std::string fallback = "line " + std::to_string(line);
    const std::optional<std::size_t> start = lineStart(xmlText, line);
    if (!start)
        return fallback;
    const std::string tag = "<" + std::string(element.Name());
    std::size_t skip = sameNameBeforeOnLine(element);
    for (std::size_t offset = xmlText.find(tag, *start); offset != std::string_view::npos;
         offset = xmlText.find(tag, offset + 1)) {
        if (!endsName(xmlText, offset + tag.size()))
            continue;
        if (skip == 0)
            return describePosition(textPosition(xmlText, offset));
        --skip;
    }
    return fallback;
}

} // namespace core
