#include "core/formats/plcopencodecheck.h"

#include "core/codegen/plcopenwriter.h"
#include "core/codegen/plcproject.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/xmlelementposition.h"
#include "core/formats/xmltext.h"
#include "core/model/iectypes.h"

#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <tuple>

namespace core {

namespace {

using tinyxml2::XMLElement;

constexpr std::size_t kMaxNamedStrangers = 10;
constexpr std::string_view kModelWins = "the embedded model is used; the edits to the code are not kept";

std::string_view localName(const XMLElement& element)
{
    std::string_view name = element.Name();
    const std::size_t colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

const XMLElement* child(const XMLElement* parent, std::string_view name)
{
    if (!parent)
        return nullptr;
    for (const XMLElement* element = parent->FirstChildElement(); element; element = element->NextSiblingElement()) {
        if (localName(*element) == name)
            return element;
    }
    return nullptr;
}

std::vector<const XMLElement*> children(const XMLElement* parent, std::string_view name)
{
    std::vector<const XMLElement*> found;
    if (!parent)
        return found;
    for (const XMLElement* element = parent->FirstChildElement(); element; element = element->NextSiblingElement()) {
        if (localName(*element) == name)
            found.push_back(element);
    }
    return found;
}

std::string attribute(const XMLElement* element, const char* name)
{
    const char* value = element ? element->Attribute(name) : nullptr;
    return value ? value : "";
}

// XML readers turn CR LF and lone CR into LF: compare what a reader sees.
std::string normalizeLineEnds(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\r')
            out += text[i];
        else if (i + 1 >= text.size() || text[i + 1] != '\n')
            out += '\n';
    }
    return out;
}

// The text of all descendants: the IEC writer puts the code in CDATA inside
// <xhtml:p>, the CODESYS writer as text inside <xhtml>.
void appendText(const tinyxml2::XMLNode& node, std::string& text)
{
    for (const tinyxml2::XMLNode* part = node.FirstChild(); part; part = part->NextSibling()) {
        if (const tinyxml2::XMLText* piece = part->ToText())
            text += piece->Value();
        else if (part->ToElement())
            appendText(*part, text);
    }
}

std::string allText(const XMLElement* element)
{
    std::string text;
    if (element)
        appendText(*element, text);
    return normalizeLineEnds(text);
}

std::string fileBody(const XMLElement& pou)
{
    return allText(child(child(&pou, "body"), "ST"));
}

std::string expectedDocumentation(const std::string& comment)
{
    return comment.empty() ? std::string() : normalizeLineEnds(xmlSafeText(plcOpenDocumentationText(comment)));
}

std::string expectedBody(const PlcPou& pou)
{
    return normalizeLineEnds(xmlSafeText(pou.body));
}

// List, name, type, initial value and documentation of one declaration, as a
// reader sees them in the file (IEC type names ignore case).
using Declaration = std::tuple<std::string, std::string, std::string, std::string, std::string>;

std::vector<Declaration> fileDeclarations(const XMLElement* list, std::string_view listName)
{
    std::vector<Declaration> declarations;
    for (const XMLElement* variable : children(list, "variable")) {
        const XMLElement* type = child(variable, "type");
        const XMLElement* typeElement = type ? type->FirstChildElement() : nullptr;
        std::string typeName;
        if (typeElement)
            typeName = localName(*typeElement) == "derived" ? attribute(typeElement, "name")
                                                            : std::string(localName(*typeElement));
        const std::string initial = attribute(child(child(variable, "initialValue"), "simpleValue"), "value");
        declarations.emplace_back(std::string(listName), attribute(variable, "name"), toUpperAscii(typeName),
                                  initial, allText(child(variable, "documentation")));
    }
    return declarations;
}

void addExpected(std::vector<Declaration>& declarations, std::string_view listName,
                 const std::vector<PlcVariable>& variables)
{
    for (const PlcVariable& variable : variables) {
        declarations.emplace_back(std::string(listName), xmlSafeAttribute(variable.name),
                                  toUpperAscii(xmlSafeAttribute(variable.typeName)),
                                  xmlSafeAttribute(variable.initialValue), expectedDocumentation(variable.comment));
    }
}

constexpr std::array<std::string_view, 4> kInterfaceLists = {"inputVars", "outputVars", "externalVars", "localVars"};

std::vector<Declaration> fileInterface(const XMLElement& pou)
{
    std::vector<Declaration> declarations;
    const XMLElement* interface = child(&pou, "interface");
    for (std::string_view listName : kInterfaceLists) {
        for (const XMLElement* list : children(interface, listName)) {
            const std::vector<Declaration> part = fileDeclarations(list, listName);
            declarations.insert(declarations.end(), part.begin(), part.end());
        }
    }
    return declarations;
}

std::vector<Declaration> expectedInterface(const PlcPou& pou)
{
    std::vector<Declaration> declarations;
    addExpected(declarations, kInterfaceLists[0], pou.inputs);
    addExpected(declarations, kInterfaceLists[1], pou.outputs);
    addExpected(declarations, kInterfaceLists[2], pou.externals);
    addExpected(declarations, kInterfaceLists[3], pou.locals);
    return declarations;
}

bool isCodesysFile(const XMLElement& project)
{
    for (const tinyxml2::XMLAttribute* a = project.FirstAttribute(); a; a = a->Next()) {
        if (kPlcOpenNamespace200 == a->Value())
            return true;
    }
    return false;
}

// IEC: the configuration's globalVars; CODESYS: the resource's GVL.
std::vector<const XMLElement*> globalLists(const XMLElement& project, bool codesys)
{
    const XMLElement* configuration = child(child(child(&project, "instances"), "configurations"), "configuration");
    return children(codesys ? child(configuration, "resource") : configuration, "globalVars");
}

class CodeComparison {
public:
    CodeComparison(std::string_view xmlText, const std::string& displayName)
        : m_text(xmlText)
        , m_file(displayName)
    {
    }

    void comparePous(const XMLElement& project, const PlcProject& expected);
    void warnAboutStrangers(const std::vector<const XMLElement*>& strangers);
    void compareGlobals(const XMLElement& project, const PlcProject& expected, bool codesys);
    void compareTask(const XMLElement& project, const PlcProject& expected, bool codesys);
    std::vector<LoadWarning> takeWarnings() { return std::move(m_warnings); }

private:
    void warn(const XMLElement* where, std::string message)
    {
        m_warnings.push_back({m_file, where ? describeElementPosition(m_text, *where) : std::string(),
                              std::move(message)});
    }

    std::string_view m_text;
    std::string m_file;
    std::vector<LoadWarning> m_warnings;
};

void CodeComparison::comparePous(const XMLElement& project, const PlcProject& expected)
{
    const XMLElement* pous = child(child(&project, "types"), "pous");
    std::vector<bool> seen(expected.pous.size(), false);
    std::vector<const XMLElement*> strangers; // POUs the model does not generate
    for (const XMLElement* pou : children(pous, "pou")) {
        const std::string name = attribute(pou, "name");
        const auto match = std::find_if(expected.pous.begin(), expected.pous.end(), [&](const PlcPou& candidate) {
            return xmlSafeAttribute(candidate.name) == name;
        });
        if (match == expected.pous.end()) {
            strangers.push_back(pou);
            continue;
        }
        seen[std::size_t(match - expected.pous.begin())] = true;
        if (fileBody(*pou) != expectedBody(*match) || fileInterface(*pou) != expectedInterface(*match)
            || allText(child(pou, "documentation")) != expectedDocumentation(match->comment)) {
            warn(pou, "the code of POU " + name + " differs from the code the embedded model generates: "
                          + std::string(kModelWins));
        }
    }
    warnAboutStrangers(strangers);
    for (std::size_t i = 0; i < seen.size(); ++i) {
        if (!seen[i]) {
            warn(pous, "the POU " + expected.pous[i].name
                           + " that the embedded model generates is missing from the file: the embedded model is "
                             "used and generates it again");
        }
    }
}

// Each position costs a pass over the text: a file with a hundred thousand
// POUs gets a few warnings, not a quadratic load time.
void CodeComparison::warnAboutStrangers(const std::vector<const XMLElement*>& strangers)
{
    const std::size_t named = std::min(strangers.size(), kMaxNamedStrangers);
    for (std::size_t i = 0; i < named; ++i) {
        warn(strangers[i], "the POU " + attribute(strangers[i], "name")
                               + " is not one the embedded model generates: the embedded model is used; this POU is "
                                 "not kept");
    }
    if (strangers.size() > named) {
        warn(strangers[named], std::to_string(strangers.size() - named)
                                   + " more POUs from here on are not ones the embedded model generates: the "
                                     "embedded model is used; they are not kept");
    }
}

void CodeComparison::compareGlobals(const XMLElement& project, const PlcProject& expected, bool codesys)
{
    const std::vector<const XMLElement*> lists = globalLists(project, codesys);
    std::vector<Declaration> found;
    for (const XMLElement* list : lists) {
        const std::vector<Declaration> part = fileDeclarations(list, "globalVars");
        found.insert(found.end(), part.begin(), part.end());
    }
    std::vector<Declaration> generated;
    addExpected(generated, "globalVars", expected.globals);
    if (found != generated) {
        warn(lists.empty() ? nullptr : lists.front(),
             "the global variables differ from those the embedded model generates: " + std::string(kModelWins));
    }
}

// The task carries the cycle time: an edited interval is lost as surely as
// edited code.
void CodeComparison::compareTask(const XMLElement& project, const PlcProject& expected, bool codesys)
{
    const XMLElement* resource =
        child(child(child(child(&project, "instances"), "configurations"), "configuration"), "resource");
    const XMLElement* task = child(resource, "task");
    const std::string name = xmlSafeAttribute(expected.taskName);
    const std::string interval = codesys ? isoTaskInterval(expected.cycleTimeMs) : iecTaskInterval(expected.cycleTimeMs);
    const std::string priority = std::to_string(std::clamp(expected.taskPriority, 0, 65535));
    if (task && attribute(task, "name") == name && attribute(task, "interval") == interval
        && attribute(task, "priority") == priority)
        return;
    warn(task ? task : resource,
         "the task differs from the one the embedded model generates (" + name + ", interval " + interval
             + ", priority " + priority + "): " + std::string(kModelWins));
}

} // namespace

std::vector<LoadWarning> plcOpenCodeDifferences(std::string_view xmlText, const XMLElement& project,
                                                const Model& model, const std::string& displayName)
{
    const bool codesys = isCodesysFile(project);
    const PlcProject expected = buildPlcProject(model, codesys ? Dialect::Codesys : Dialect::Iec);
    CodeComparison comparison(xmlText, displayName);
    comparison.comparePous(project, expected);
    comparison.compareGlobals(project, expected, codesys);
    comparison.compareTask(project, expected, codesys);
    return comparison.takeWarnings();
}

} // namespace core
