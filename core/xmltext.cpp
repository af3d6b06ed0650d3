#include "core/xmltext.h"

#include <algorithm>

namespace core {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD"; // U+FFFD

bool isAllowedInXml(char32_t c)
{
    return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD)
        || (c >= 0x10000 && c <= 0x10FFFF);
}

bool isContinuation(unsigned char byte)
{
    return (byte & 0xC0) == 0x80;
}

// Length of the well-formed UTF-8 sequence at text[i] (shortest form, no
// surrogates, at most U+10FFFF), or 0 when the bytes there are not one.
std::size_t decodeUtf8(std::string_view text, std::size_t i, char32_t& code)
{
    const auto lead = static_cast<unsigned char>(text[i]);
    std::size_t length = 0;
    char32_t minimum = 0;
    if (lead < 0x80) {
        code = lead;
        return 1;
    } else if ((lead & 0xE0) == 0xC0) {
        length = 2, code = lead & 0x1F, minimum = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3, code = lead & 0x0F, minimum = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4, code = lead & 0x07, minimum = 0x10000;
    } else {
        return 0;
    }
    if (i + length > text.size())
        return 0;
    for (std::size_t k = 1; k < length; ++k) {
        const auto byte = static_cast<unsigned char>(text[i + k]);
        if (!isContinuation(byte))
            return 0;
        code = (code << 6) | (byte & 0x3F);
    }
    const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    return code < minimum || surrogate || code > 0x10FFFF ? 0 : length;
}

bool isPlainAscii(std::string_view text, bool attribute)
{
    return std::all_of(text.begin(), text.end(), [attribute](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return (byte >= 0x20 && byte < 0x7F) || (!attribute && (c == '\n' || c == '\t' || c == '\r'));
    });
}

std::string sanitize(std::string_view text, bool attribute)
{
    if (isPlainAscii(text, attribute))
        return std::string(text);
    std::string out;
    out.reserve(text.size());
    std::size_t i = 0;
    while (i < text.size()) {
        char32_t code = 0;
        const std::size_t length = decodeUtf8(text, i, code);
        if (length == 0) {
            out += kReplacement;
            ++i;
            continue;
        }
        if (attribute && (code == '\t' || code == '\n' || code == '\r'))
            out += ' ';
        else if (isAllowedInXml(code))
            out.append(text.substr(i, length));
        else
            out += kReplacement;
        i += length;
    }
    return out;
}

} // namespace

std::string xmlSafeText(std::string_view text)
{
    return sanitize(text, false);
}

std::string xmlSafeAttribute(std::string_view text)
{
    return sanitize(text, true);
}

} // namespace core
