#include "core/checks/diagnostic.h"

#include <algorithm>
#include <cstdio>

namespace core {

std::string_view severityName(Severity severity)
{
    switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Info: return "info";
    }
    return "?";
}

std::string diagnosticElementLabel(const Diagnostic& diagnostic)
{
    if (diagnostic.target == Diagnostic::Target::Model || diagnostic.element.empty())
        return "model";
    if (diagnostic.target == Diagnostic::Target::GrafcetStep)
        return diagnostic.element + " step " + std::to_string(diagnostic.nestedNumber);
    if (diagnostic.target == Diagnostic::Target::GrafcetTransition)
        return diagnostic.element + " T" + std::to_string(diagnostic.nestedNumber);
    switch (diagnostic.target) {
    case Diagnostic::Target::Mode: return "mode " + diagnostic.element;
    case Diagnostic::Target::Command: return "command " + diagnostic.element;
    case Diagnostic::Target::ModeState: return diagnostic.element + ": " + diagnostic.state;
    case Diagnostic::Target::Request: return "request of mode " + diagnostic.element;
    case Diagnostic::Target::MachineComponent: return "machine component " + diagnostic.element;
    default: return diagnostic.element;
    }
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

Utf8Character decodeUtf8(std::string_view text)
{
    Utf8Character invalid;
    if (text.empty())
        return invalid;
    const auto lead = static_cast<unsigned char>(text[0]);
    if (lead < 0x80)
        return Utf8Character{lead, 1, true};
    std::size_t length = 0;
    char32_t codePoint = 0;
    char32_t smallest = 0; // below it, the sequence is overlong
    if ((lead & 0xE0) == 0xC0) {
        length = 2;
        codePoint = lead & 0x1F;
        smallest = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3;
        codePoint = lead & 0x0F;
        smallest = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4;
        codePoint = lead & 0x07;
        smallest = 0x10000;
    } else {
        return invalid;
    }
    if (text.size() < length)
        return invalid;
    for (std::size_t i = 1; i < length; ++i) {
        const auto next = static_cast<unsigned char>(text[i]);
        if ((next & 0xC0) != 0x80)
            return invalid;
        codePoint = (codePoint << 6) | (next & 0x3F);
    }
    if (codePoint < smallest || codePoint > 0x10FFFF || (codePoint >= 0xD800 && codePoint <= 0xDFFF))
        return invalid;
    return Utf8Character{codePoint, length, true};
}

bool isControlCharacter(char32_t c)
{
    return c < 0x20 || (c >= 0x7F && c <= 0x9F) || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069)
        || c == 0x2028 || c == 0x2029;
}

namespace {

void appendHex(std::string& out, const char* prefix, unsigned value, int digits)
{
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%s%0*x", prefix, digits, value);
    out += buffer;
}

} // namespace

std::string escapeControlCharacters(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    while (!text.empty()) {
        const Utf8Character character = decodeUtf8(text);
        const char32_t c = character.codePoint;
        if (!character.valid) {
            appendHex(out, "\\x", static_cast<unsigned char>(text[0]), 2);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\\') {
            out += "\\\\";
        } else if (c < 0x20 || c == 0x7F) {
            appendHex(out, "\\x", static_cast<unsigned>(c), 2);
        } else if (isControlCharacter(c)) {
            appendHex(out, "\\u", static_cast<unsigned>(c), 4);
        } else {
            out.append(text.substr(0, character.length));
        }
        text.remove_prefix(character.length);
    }
    return out;
}

} // namespace core
