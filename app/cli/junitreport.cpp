#include "junitreport.h"

#include <cstdio>

namespace cli {

namespace {

// The length of the UTF-8 sequence at text[i], 0 when it is not one.
std::size_t utf8Length(std::string_view text, std::size_t i)
{
    const auto byte = [&](std::size_t at) { return static_cast<unsigned char>(text[at]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    unsigned int minimum = 0;
    unsigned int code = 0;
    if (lead < 0x80)
        return 1;
    if ((lead & 0xE0u) == 0xC0u) {
        length = 2, minimum = 0x80, code = lead & 0x1Fu;
    } else if ((lead & 0xF0u) == 0xE0u) {
        length = 3, minimum = 0x800, code = lead & 0x0Fu;
    } else if ((lead & 0xF8u) == 0xF0u) {
        length = 4, minimum = 0x10000, code = lead & 0x07u;
    } else {
        return 0;
    }
    if (i + length > text.size())
        return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0u) != 0x80u)
            return 0;
        code = (code << 6) | (byte(i + k) & 0x3Fu);
    }
    // Overlong forms, surrogates and what lies past Unicode are not UTF-8;
    // U+FFFE and U+FFFF are not XML characters.
    if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF) || code == 0xFFFE || code == 0xFFFF)
        return 0;
    return length;
}

std::string hexByte(unsigned char byte)
{
    char text[8];
    std::snprintf(text, sizeof text, "\\x%02x", byte);
    return text;
}

void appendAttribute(std::string& out, std::string_view name, std::string_view value)
{
    out += " ";
    out += name;
    out += "=\"" + escapeXml(value) + "\"";
}

std::size_t count(const JUnitSuite& suite, JUnitCase::Outcome outcome)
{
    std::size_t n = 0;
    for (const JUnitCase& c : suite.cases)
        n += c.outcome == outcome ? 1 : 0;
    return n;
}

void writeCase(std::string& out, const JUnitSuite& suite, const JUnitCase& test)
{
    out += "    <testcase";
    appendAttribute(out, "name", test.name);
    appendAttribute(out, "classname", suite.name);
    if (test.outcome == JUnitCase::Outcome::Passed) {
        out += "/>\n";
        return;
    }
    const char* element = test.outcome == JUnitCase::Outcome::Failed ? "failure" : "error";
    out += ">\n      <";
    out += element;
    appendAttribute(out, "message", test.message);
    appendAttribute(out, "type", test.outcome == JUnitCase::Outcome::Failed ? "ScenarioFailure" : "ScenarioError");
    out += ">" + escapeXml(test.details) + "</" + element + ">\n    </testcase>\n";
}

} // namespace

std::string escapeXml(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        switch (c) {
        case '&': out += "&amp;"; ++i; continue;
        case '<': out += "&lt;"; ++i; continue;
        case '>': out += "&gt;"; ++i; continue;
        case '"': out += "&quot;"; ++i; continue;
        case '\'': out += "&apos;"; ++i; continue;
        case '\n': out += "&#10;"; ++i; continue; // kept through attribute normalisation
        case '\t': out += "&#9;"; ++i; continue;
        default: break;
        }
        const auto byte = static_cast<unsigned char>(c);
        const std::size_t length = utf8Length(text, i);
        if (length == 0 || byte < 0x20 || byte == 0x7F) {
            out += hexByte(byte);
            ++i;
            continue;
        }
        out.append(text.substr(i, length));
        i += length;
    }
    return out;
}

std::string writeJUnit(const std::vector<JUnitSuite>& suites)
{
    std::size_t tests = 0;
    std::size_t failures = 0;
    std::size_t errors = 0;
    for (const JUnitSuite& suite : suites) {
        tests += suite.cases.size();
        failures += count(suite, JUnitCase::Outcome::Failed);
        errors += count(suite, JUnitCase::Outcome::Error);
    }
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites";
    appendAttribute(out, "name", "ggstudio-cli test");
    appendAttribute(out, "tests", std::to_string(tests));
    appendAttribute(out, "failures", std::to_string(failures));
    appendAttribute(out, "errors", std::to_string(errors));
    out += ">\n";
    for (const JUnitSuite& suite : suites) {
        out += "  <testsuite";
        appendAttribute(out, "name", suite.name);
        appendAttribute(out, "tests", std::to_string(suite.cases.size()));
        appendAttribute(out, "failures", std::to_string(count(suite, JUnitCase::Outcome::Failed)));
        appendAttribute(out, "errors", std::to_string(count(suite, JUnitCase::Outcome::Error)));
        appendAttribute(out, "skipped", "0");
        out += ">\n";
        for (const JUnitCase& test : suite.cases)
            writeCase(out, suite, test);
        out += "  </testsuite>\n";
    }
    out += "</testsuites>\n";
    return out;
}

} // namespace cli
