#include "core/layout/grafcetactiontext.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace core {

namespace {

std::string trimmed(std::string_view text)
{
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])))
        ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])))
        --end;
    return std::string(text.substr(begin, end - begin));
}

} // namespace

ActionParts splitAction(const GrafcetAction& action)
{
    ActionParts parts;
    std::string body = trimmed(action.text);
    std::size_t space = 0;
    while (space < body.size() && !std::isspace(static_cast<unsigned char>(body[space])))
        ++space;
    const std::string_view word = std::string_view(body).substr(0, space);
    const std::string rest = trimmed(std::string_view(body).substr(space));
    std::string qualifier;
    if ((equalsIgnoreCase(word, "N") || equalsIgnoreCase(word, "S") || equalsIgnoreCase(word, "R"))
        && !rest.empty() && rest.rfind(":=", 0) != 0) {
        qualifier = std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(word[0]))));
        body = rest;
    }
    if (action.timing == ActionTiming::Continuous) {
        // " IF " as a word separates the condition.
        std::size_t at = 0;
        while (at < body.size()) {
            const std::size_t start = body.find_first_not_of(" \t\r\n", at);
            if (start == std::string::npos)
                break;
            std::size_t stop = body.find_first_of(" \t\r\n", start);
            if (stop == std::string::npos)
                stop = body.size();
            if (start > 0 && equalsIgnoreCase(std::string_view(body).substr(start, stop - start), "IF")) {
                parts.condition = trimmed(std::string_view(body).substr(stop));
                body = trimmed(std::string_view(body).substr(0, start));
                break;
            }
            at = stop;
        }
        parts.qualifier = qualifier == "N" ? "" : qualifier;
    } else {
        const char* mark = action.timing == ActionTiming::OnActivation ? "\xE2\x86\x91" : "\xE2\x86\x93"; // ↑ ↓
        parts.qualifier = std::string(mark) + (qualifier == "N" ? "" : qualifier);
    }
    parts.text = body;
    return parts;
}

} // namespace core
