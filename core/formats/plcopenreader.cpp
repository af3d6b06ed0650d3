#include "core/formats/plcopenreader.h"

#include "core/formats/fileio.h"
#include "core/formats/nativeformat.h"
#include "core/codegen/plcopenwriter.h"
#include "core/formats/plcopencodecheck.h"
#include "core/formats/xmlelementposition.h"
#include "core/formats/xmltext.h"

#include <tinyxml2.h>


namespace core {

namespace {

using tinyxml2::XMLElement;

// tinyxml2 knows no namespaces: elements are matched by local name, so that
// a file whose PLCopen prefix is not the default one still reads.
std::string_view localName(const XMLElement* element)
{
    std::string_view name = element->Name();
    const std::size_t colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// Only reached if tinyxml2 refuses what checkWellFormedXml let through, which
// the tests and the fuzzer have not seen: tinyxml2 gives the line only.
std::string describeXmlError(tinyxml2::XMLError error)
{
    switch (error) {
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: return "the file holds no XML element";
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT: return "an element is not closed by its matching end tag";
    case tinyxml2::XML_ERROR_PARSING_ELEMENT: return "malformed element";
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE: return "malformed attribute";
    case tinyxml2::XML_ERROR_PARSING_TEXT: return "malformed text (an unescaped '<' or '&'?)";
    case tinyxml2::XML_ERROR_PARSING_CDATA: return "unterminated CDATA section";
    case tinyxml2::XML_ERROR_PARSING_COMMENT: return "unterminated comment";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION: return "malformed XML declaration";
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN: return "malformed markup";
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED: return "elements nested too deeply";
    default: return "malformed XML";
    }
}

// All text and CDATA children joined: the writer splits CDATA around "]]>".
std::string textContent(const XMLElement* element)
{
    std::string text;
    for (const tinyxml2::XMLNode* child = element->FirstChild(); child; child = child->NextSibling()) {
        if (const tinyxml2::XMLText* piece = child->ToText())
            text += piece->Value();
    }
    return text;
}

// Every element that carries a model: the children of each addData entry
// named kPlcOpenModelDataName (the writer puts one, in one entry).
std::vector<const XMLElement*> findModelElements(const XMLElement* project)
{
    std::vector<const XMLElement*> models;
    for (const XMLElement* addData = project->FirstChildElement(); addData; addData = addData->NextSiblingElement()) {
        if (localName(addData) != "addData")
            continue;
        for (const XMLElement* data = addData->FirstChildElement(); data; data = data->NextSiblingElement()) {
            const char* name = data->Attribute("name");
            if (localName(data) != "data" || !name || kPlcOpenModelDataName != name)
                continue;
            for (const XMLElement* model = data->FirstChildElement(); model; model = model->NextSiblingElement())
                models.push_back(model);
        }
    }
    return models;
}

LoadError embeddedModelError(const LoadError& inner, const std::string& displayName)
{
    std::string location = "embedded model";
    if (!inner.location.empty())
        location += " " + inner.location;
    return {displayName, location, "the GG Studio model inside this PLCopen file is invalid: " + inner.message};
}

} // namespace

std::variant<std::unique_ptr<Model>, LoadError> readPlcOpenModel(std::string_view xmlText,
                                                                 const std::string& displayName,
                                                                 std::vector<LoadWarning>* warnings)
{
    // tinyxml2 accepts too much (a second root, undeclared entities, &#0;) and
    // is quadratic in the attributes of an element: it only sees checked text.
    const XmlCheck check = checkWellFormedXml(xmlText);
    if (check.problem) {
        return LoadError{displayName, describePosition(textPosition(xmlText, check.problem->offset)),
                         "not well-formed XML: " + check.problem->message};
    }
    tinyxml2::XMLDocument document;
    const tinyxml2::XMLError error = document.Parse(xmlText.data(), xmlText.size());
    if (error != tinyxml2::XML_SUCCESS) {
        const int line = document.ErrorLineNum();
        return LoadError{displayName, line > 0 ? "line " + std::to_string(line) : std::string(),
                         "not well-formed XML: " + describeXmlError(error)};
    }
    const XMLElement* root = document.RootElement();
    if (!root)
        return LoadError{displayName, {}, "not well-formed XML: the file holds no XML element"};
    if (localName(root) != "project") {
        return LoadError{displayName, describePosition(textPosition(xmlText, check.rootOffset)),
                         "not a PLCopen XML file: the root element is <" + std::string(root->Name())
                             + ">, a PLCopen file starts with <project>"};
    }
    const std::vector<const XMLElement*> models = findModelElements(root);
    if (models.size() > 1) {
        return LoadError{displayName, describeElementPosition(xmlText, *models[1]),
                         "a second GG Studio model (the first is at " + describeElementPosition(xmlText, *models[0])
                             + "): GG Studio cannot tell which one the file means, so it opens neither"};
    }
    const XMLElement* model = models.empty() ? nullptr : models.front();
    if (!model) {
        return LoadError{displayName, {},
                         "a PLCopen file without a GG Studio model: GG Studio can only open PLCopen files it "
                         "exported (they carry the model in the project's addData '"
                             + std::string(kPlcOpenModelDataName) + "')"};
    }
    auto loaded = loadNativeJson(textContent(model), displayName);
    if (auto* failure = std::get_if<LoadError>(&loaded))
        return embeddedModelError(*failure, displayName);
    if (warnings)
        *warnings = plcOpenCodeDifferences(xmlText, *root, *std::get<std::unique_ptr<Model>>(loaded), displayName);
    return loaded;
}

} // namespace core
