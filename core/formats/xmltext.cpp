#include "core/formats/xmltext.h"

#include "core/formats/fileio.h"
#include "core/model/iectypes.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

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


// --- Well-formedness ------------------------------------------------------

std::string codePointName(char32_t code)
{
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(code));
    return buffer;
}

// A reference or name quoted in a message, cut short so that a megabyte of
// digits does not end up in it.
std::string cutShort(std::string_view text)
{
    constexpr std::size_t kLongest = 40;
    return text.size() <= kLongest ? std::string(text) : std::string(text.substr(0, kLongest)) + "...";
}

std::optional<XmlProblem> findForbiddenCharacter(std::string_view text)
{
    std::size_t i = 0;
    while (i < text.size()) {
        char32_t code = 0;
        const std::size_t length = decodeUtf8(text, i, code);
        if (length == 0)
            return XmlProblem{i, "invalid UTF-8 (GG Studio reads PLCopen files in UTF-8)"};
        if (code == 0)
            return XmlProblem{i, "a NUL byte (U+0000), which XML 1.0 cannot carry"};
        if (!isAllowedInXml(code))
            return XmlProblem{i, "the character " + codePointName(code) + ", which XML 1.0 cannot carry"};
        i += length;
    }
    return std::nullopt;
}

bool isNameStartChar(char32_t c)
{
    return c == ':' || c == '_' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= 0xC0 && c <= 0xD6)
        || (c >= 0xD8 && c <= 0xF6) || (c >= 0xF8 && c <= 0x2FF) || (c >= 0x370 && c <= 0x37D)
        || (c >= 0x37F && c <= 0x1FFF) || (c >= 0x200C && c <= 0x200D) || (c >= 0x2070 && c <= 0x218F)
        || (c >= 0x2C00 && c <= 0x2FEF) || (c >= 0x3001 && c <= 0xD7FF) || (c >= 0xF900 && c <= 0xFDCF)
        || (c >= 0xFDF0 && c <= 0xFFFD) || (c >= 0x10000 && c <= 0xEFFFF);
}

bool isNameChar(char32_t c)
{
    return isNameStartChar(c) || c == '-' || c == '.' || (c >= '0' && c <= '9') || c == 0xB7
        || (c >= 0x300 && c <= 0x36F) || (c >= 0x203F && c <= 0x2040);
}

bool isXmlSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool isPredefinedEntity(std::string_view name)
{
    return name == "lt" || name == "gt" || name == "amp" || name == "apos" || name == "quot";
}

struct OpenElement {
    std::string_view name;
    std::size_t offset;
};

// A thrown problem ends the scan at the first error; the check is the only
// catcher, so no exception leaves this file.
struct Malformed {
    XmlProblem problem;
};

// Runs over text already known to hold only XML characters in valid UTF-8.
class WellFormednessScanner {
public:
    explicit WellFormednessScanner(std::string_view text) : m_text(text) {}

    std::size_t scanDocument()
    {
        if (m_text.substr(0, 3) == "\xEF\xBB\xBF")
            m_pos = 3;
        if (startsXmlDeclaration())
            scanXmlDeclaration();
        std::optional<std::size_t> root;
        while (true) {
            skipSpaces();
            if (atEnd())
                break;
            if (lookingAt("<!--")) {
                scanComment();
            } else if (lookingAt("<?")) {
                scanProcessingInstruction();
            } else if (lookingAt("<!DOCTYPE")) {
                fail(m_pos, "a DOCTYPE: GG Studio reads no document type declaration and expands no entity "
                            "(PLCopen files have none)");
            } else if (m_text[m_pos] == '<' && nameStartsAt(m_pos + 1)) {
                if (root)
                    fail(m_pos, "a second root element <" + std::string(nameAt(m_pos + 1))
                                    + ">: an XML file has exactly one root element");
                root = m_pos;
                scanElement();
            } else if (m_text[m_pos] == '<') {
                fail(m_pos, root ? "markup after the root element" : "malformed markup before the root element");
            } else {
                fail(m_pos, root ? "text after the root element" : "text before the root element");
            }
        }
        if (!root)
            fail(m_pos, "the file holds no XML element");
        return *root;
    }

private:
    [[noreturn]] void fail(std::size_t offset, std::string message) const
    {
        throw Malformed{{offset, std::move(message)}};
    }

    bool atEnd() const { return m_pos >= m_text.size(); }
    bool lookingAt(std::string_view token) const { return m_text.substr(m_pos, token.size()) == token; }

    char32_t codeAt(std::size_t offset, std::size_t& length) const
    {
        char32_t code = 0;
        length = offset < m_text.size() ? decodeUtf8(m_text, offset, code) : 0;
        return length == 0 ? 0 : code;
    }

    bool nameStartsAt(std::size_t offset) const
    {
        std::size_t length = 0;
        const char32_t code = codeAt(offset, length);
        return length > 0 && isNameStartChar(code);
    }

    std::string_view nameAt(std::size_t offset) const
    {
        std::size_t end = offset;
        std::size_t length = 0;
        while (end < m_text.size() && isNameChar(codeAt(end, length)))
            end += length;
        return m_text.substr(offset, end - offset);
    }

    std::string_view readName(const char* what)
    {
        if (!nameStartsAt(m_pos))
            fail(m_pos, std::string("expected ") + what);
        const std::string_view name = nameAt(m_pos);
        m_pos += name.size();
        return name;
    }

    bool skipSpaces()
    {
        const std::size_t start = m_pos;
        while (!atEnd() && isXmlSpace(m_text[m_pos]))
            ++m_pos;
        return m_pos > start;
    }

    // Moves past the terminator; fails at start when there is none.
    void skipPast(std::string_view terminator, std::size_t start, const char* what)
    {
        const std::size_t end = m_text.find(terminator, m_pos);
        if (end == std::string_view::npos)
            fail(start, std::string(what) + " is not closed by '" + std::string(terminator) + "'");
        m_pos = end + terminator.size();
    }

    bool startsXmlDeclaration() const
    {
        return m_text.substr(m_pos, 5) == "<?xml" && m_pos + 5 < m_text.size()
            && (isXmlSpace(m_text[m_pos + 5]) || m_text[m_pos + 5] == '?');
    }

    void scanXmlDeclaration()
    {
        const std::size_t start = m_pos;
        m_pos += 5;
        std::vector<std::pair<std::string_view, std::string_view>> pseudoAttributes;
        while (true) {
            const bool spaced = skipSpaces();
            if (lookingAt("?>"))
                break;
            if (!spaced)
                fail(m_pos, "expected a space or '?>' in the XML declaration");
            const std::size_t nameOffset = m_pos;
            const std::string_view name = readName("'version', 'encoding' or 'standalone' in the XML declaration");
            pseudoAttributes.emplace_back(name, scanAttributeValue(name, nameOffset));
        }
        m_pos += 2;
        checkXmlDeclaration(pseudoAttributes, start);
    }

    void checkXmlDeclaration(const std::vector<std::pair<std::string_view, std::string_view>>& items,
                             std::size_t start) const
    {
        std::size_t next = 0;
        if (items.empty() || items[0].first != "version")
            fail(start, "the XML declaration does not start with its version");
        const std::string_view version = items[next++].second;
        // XML 1.1 allows control characters by reference that 1.0 refuses.
        if (version != "1.0")
            fail(start, "XML version '" + cutShort(version) + "' is not read: GG Studio reads XML 1.0");
        if (next < items.size() && items[next].first == "encoding") {
            const std::string_view encoding = items[next++].second;
            if (!equalsIgnoreCase(encoding, "UTF-8"))
                fail(start, "the encoding '" + cutShort(encoding) + "': GG Studio reads PLCopen files in UTF-8");
        }
        if (next < items.size() && items[next].first == "standalone") {
            const std::string_view standalone = items[next++].second;
            if (standalone != "yes" && standalone != "no")
                fail(start, "standalone must be 'yes' or 'no' in the XML declaration");
        }
        if (next < items.size())
            fail(start, "'" + cutShort(items[next].first) + "' out of place in the XML declaration "
                            "(version, then encoding, then standalone)");
    }

    void scanComment()
    {
        const std::size_t start = m_pos;
        m_pos += 4;
        const std::size_t dashes = m_text.find("--", m_pos);
        if (dashes == std::string_view::npos)
            fail(start, "a comment is not closed by '-->'");
        if (m_text.substr(dashes, 3) != "-->")
            fail(dashes, "'--' inside a comment");
        m_pos = dashes + 3;
    }

    void scanProcessingInstruction()
    {
        const std::size_t start = m_pos;
        m_pos += 2;
        const std::string_view target = readName("a processing instruction's target after '<?'");
        if (equalsIgnoreCase(target, "xml"))
            fail(start, "an XML declaration that is not at the very start of the file");
        if (!lookingAt("?>") && !skipSpaces())
            fail(m_pos, "expected a space or '?>' after the processing instruction's target");
        skipPast("?>", start, "a processing instruction");
    }

    // At '&': a character reference to an XML character or one of the five
    // predefined entities, and nothing else.
    void scanReference()
    {
        const std::size_t start = m_pos;
        ++m_pos;
        if (lookingAt("#")) {
            scanCharacterReference(start);
            return;
        }
        if (!nameStartsAt(m_pos))
            fail(start, "a '&' that starts no reference (write it as &amp;)");
        const std::string_view name = nameAt(m_pos);
        m_pos += name.size();
        if (atEnd() || m_text[m_pos] != ';') {
            // "R&D" is a raw '&', "&amp" a reference cut short.
            if (!isPredefinedEntity(name))
                fail(start, "a '&' that starts no reference (write it as &amp;)");
            fail(start, "the reference &" + cutShort(name) + " is not closed by ';'");
        }
        ++m_pos;
        if (!isPredefinedEntity(name))
            fail(start, "the entity &" + cutShort(name)
                            + "; is not declared (XML predefines only &lt; &gt; &amp; &apos; &quot;)");
    }

    void scanCharacterReference(std::size_t start)
    {
        ++m_pos; // '#'
        const bool hex = lookingAt("x");
        if (hex)
            ++m_pos;
        const std::size_t digitsStart = m_pos;
        std::uint32_t value = 0;
        bool beyond = false;
        while (!atEnd()) {
            const int digit = digitValue(m_text[m_pos], hex);
            if (digit < 0)
                break;
            value = value * (hex ? 16 : 10) + static_cast<std::uint32_t>(digit);
            beyond = beyond || value > 0x10FFFF;
            if (beyond)
                value = 0x110000; // stays above the range without overflowing
            ++m_pos;
        }
        if (m_pos == digitsStart || atEnd() || m_text[m_pos] != ';')
            fail(start, std::string("a malformed character reference: expected ") + (hex ? "hexadecimal " : "")
                            + "digits and ';' after '" + (hex ? "&#x" : "&#") + "'");
        ++m_pos;
        const std::string reference = cutShort(m_text.substr(start, m_pos - start));
        const auto code = static_cast<char32_t>(value);
        if (beyond)
            fail(start, "the character reference " + reference + " is beyond U+10FFFF, the last Unicode character");
        if (code == 0)
            fail(start, "the character reference " + reference + " stands for U+0000 (NUL), which XML 1.0 cannot carry");
        if (code >= 0xD800 && code <= 0xDFFF)
            fail(start, "the character reference " + reference + " stands for " + codePointName(code)
                            + ", a surrogate, which XML 1.0 cannot carry");
        if (!isAllowedInXml(code))
            fail(start, "the character reference " + reference + " stands for " + codePointName(code)
                            + ", which XML 1.0 cannot carry");
    }

    static int digitValue(char c, bool hex)
    {
        if (c >= '0' && c <= '9')
            return c - '0';
        if (hex && c >= 'a' && c <= 'f')
            return c - 'a' + 10;
        if (hex && c >= 'A' && c <= 'F')
            return c - 'A' + 10;
        return -1;
    }

    // At the opening quote; returns the raw value and moves past the closing quote.
    std::string_view scanAttributeValue(std::string_view name, std::size_t nameOffset)
    {
        skipSpaces();
        if (!lookingAt("="))
            fail(m_pos, "expected '=' after the attribute '" + cutShort(name) + "'");
        ++m_pos;
        skipSpaces();
        if (atEnd() || (m_text[m_pos] != '"' && m_text[m_pos] != '\''))
            fail(m_pos, "the value of the attribute '" + cutShort(name) + "' is not quoted");
        const char quote = m_text[m_pos++];
        const std::size_t valueStart = m_pos;
        while (true) {
            if (atEnd())
                fail(nameOffset, "the value of the attribute '" + cutShort(name) + "' is not closed by " + quote);
            const char c = m_text[m_pos];
            if (c == quote)
                break;
            if (c == '<')
                fail(m_pos, "a '<' in the value of the attribute '" + cutShort(name) + "' (write it as &lt;)");
            if (c == '&')
                scanReference();
            else
                ++m_pos;
        }
        return m_text.substr(valueStart, m_pos++ - valueStart);
    }

    // At '<' of a start tag; returns true when the element is empty (<a/>).
    bool scanStartTag()
    {
        const std::size_t start = m_pos++;
        const std::string_view element = readName("an element name after '<'");
        if (m_open.size() >= kMaxXmlDepth)
            fail(start, "elements nested deeper than " + std::to_string(kMaxXmlDepth) + " levels");
        m_attributeNames.clear();
        while (true) {
            const bool spaced = skipSpaces();
            if (lookingAt("/>")) {
                m_pos += 2;
                return true;
            }
            if (lookingAt(">")) {
                ++m_pos;
                m_open.push_back({element, start});
                return false;
            }
            if (atEnd())
                fail(start, "the start tag <" + cutShort(element) + "> is not closed by '>'");
            if (!spaced)
                fail(m_pos, "expected a space, '>' or '/>' in the start tag <" + cutShort(element) + ">");
            scanAttribute(element);
        }
    }

    void scanAttribute(std::string_view element)
    {
        const std::size_t nameOffset = m_pos;
        if (!nameStartsAt(m_pos))
            fail(m_pos, "expected an attribute name, '>' or '/>' in the start tag <" + cutShort(element) + ">");
        const std::string_view name = readName("an attribute name");
        // The cap keeps this search bounded, and the whole scan linear.
        if (std::find(m_attributeNames.begin(), m_attributeNames.end(), name) != m_attributeNames.end())
            fail(nameOffset, "the attribute '" + cutShort(name) + "' appears twice in <" + cutShort(element) + ">");
        if (m_attributeNames.size() == kMaxXmlAttributesPerElement)
            fail(nameOffset, "the element <" + cutShort(element) + "> has more than "
                                 + std::to_string(kMaxXmlAttributesPerElement) + " attributes (GG Studio reads at most "
                                 + std::to_string(kMaxXmlAttributesPerElement) + " on one element)");
        m_attributeNames.push_back(name);
        scanAttributeValue(name, nameOffset);
    }

    void scanEndTag()
    {
        const std::size_t start = m_pos;
        m_pos += 2;
        const std::string_view name = readName("an element name after '</'");
        skipSpaces();
        if (!lookingAt(">"))
            fail(m_pos, "expected '>' to close the end tag </" + cutShort(name) + ">");
        ++m_pos;
        const OpenElement& open = m_open.back();
        if (name != open.name) {
            fail(start, "an element is not closed by its matching end tag: </" + cutShort(name) + "> here closes <"
                            + cutShort(open.name) + "> of "
                            + describePosition(textPosition(m_text, open.offset)));
        }
        m_open.pop_back();
    }

    // At the root's '<': the root element and everything in it.
    void scanElement()
    {
        if (scanStartTag())
            return;
        while (!m_open.empty()) {
            if (atEnd())
                fail(m_open.back().offset, "the element <" + cutShort(m_open.back().name) + "> is not closed");
            const char c = m_text[m_pos];
            if (c == '&')
                scanReference();
            else if (c == '<')
                scanMarkupInContent();
            else if (c == ']' && lookingAt("]]>"))
                fail(m_pos, "']]>' in text (write it as ]]&gt;)");
            else
                ++m_pos;
        }
    }

    void scanMarkupInContent()
    {
        if (lookingAt("</")) {
            scanEndTag();
        } else if (lookingAt("<!--")) {
            scanComment();
        } else if (lookingAt("<![CDATA[")) {
            const std::size_t start = m_pos;
            m_pos += 9;
            skipPast("]]>", start, "a CDATA section");
        } else if (lookingAt("<?")) {
            scanProcessingInstruction();
        } else if (nameStartsAt(m_pos + 1)) {
            scanStartTag();
        } else {
            fail(m_pos, "a '<' that starts no markup (write it as &lt;)");
        }
    }

    std::string_view m_text;
    std::size_t m_pos = 0;
    std::vector<OpenElement> m_open;
    std::vector<std::string_view> m_attributeNames; // of the start tag being read
};

} // namespace

std::string xmlSafeText(std::string_view text)
{
    return sanitize(text, false);
}

std::string xmlSafeAttribute(std::string_view text)
{
    return sanitize(text, true);
}

XmlCheck checkWellFormedXml(std::string_view text)
{
    XmlCheck check;
    check.problem = findForbiddenCharacter(text);
    if (check.problem)
        return check;
    try {
        check.rootOffset = WellFormednessScanner(text).scanDocument();
    } catch (const Malformed& malformed) {
        check.problem = malformed.problem;
    }
    return check;
}

} // namespace core
