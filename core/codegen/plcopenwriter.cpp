#include "core/codegen/plcopenwriter.h"

#include "core/model/iectypes.h"
#include "core/formats/nativeformat.h"
#include "core/formats/xmltext.h"

#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>

namespace core {

namespace {

using tinyxml2::XMLElement;

constexpr const char* kCodesysAttributesData = "http://www.3s-software.com/plcopenxml/attributes";
constexpr const char* kCodesysTaskSettingsData = "http://www.3s-software.com/plcopenxml/tasksettings";

// The elementary types of the schema's elementaryTypes group that a
// generated declaration can use; anything else is a derived type (an FB).
bool isElementaryTypeName(std::string_view name)
{
    static constexpr std::array<std::string_view, 19> names = {
        "BOOL", "BYTE", "WORD",  "DWORD", "LWORD", "SINT", "INT",  "DINT", "LINT", "USINT",
        "UINT", "UDINT", "ULINT", "REAL", "LREAL", "TIME", "DATE", "DT",   "TOD"};
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The embedded model must come back exactly. Its JSON already escapes the
// control characters XML 1.0 cannot carry (as \u0001 ...); the two other
// characters XML refuses, the noncharacters U+FFFE and U+FFFF, are written
// as JSON escapes too, which the native reader turns back into them, instead
// of becoming U+FFFD in the XML. Their UTF-8 bytes only ever occur inside
// JSON strings, where an escape means the same character.
std::string escapeXmlNoncharacters(std::string_view json)
{
    static constexpr std::string_view fffe = "\xEF\xBF\xBE";
    static constexpr std::string_view ffff = "\xEF\xBF\xBF";
    std::string out;
    out.reserve(json.size());
    std::string_view rest = json;
    while (!rest.empty()) {
        if (rest.starts_with(fffe) || rest.starts_with(ffff)) {
            out += rest.starts_with(fffe) ? "\\ufffe" : "\\uffff";
            rest.remove_prefix(fffe.size());
        } else {
            out += rest.front();
            rest.remove_prefix(1);
        }
    }
    return out;
}

class PlcOpenWriter {
public:
    PlcOpenWriter(const PlcProject& project, const Model& model, const PlcOpenOptions& options)
        : m_project(project)
        , m_model(model)
        , m_options(options)
        , m_codesys(project.dialect == Dialect::Codesys)
    {
    }

    std::string write();

private:
    XMLElement* add(XMLElement* parent, const char* name);
    static void attribute(XMLElement* element, const char* name, std::string_view value);
    void cdata(XMLElement* parent, std::string_view text);
    void formattedText(XMLElement* parent, std::string_view text);

    void writeHeaders(XMLElement* root);
    void writeTypes(XMLElement* root);
    void writePou(XMLElement* pous, const PlcPou& pou);
    void writeInterface(XMLElement* element, const PlcPou& pou);
    void writeVarList(XMLElement* parent, const char* listName, const std::vector<PlcVariable>& variables);
    void writeVariables(XMLElement* list, const std::vector<PlcVariable>& variables);
    void writeVariable(XMLElement* list, const PlcVariable& variable);
    void writeInstances(XMLElement* root);
    void writeTask(XMLElement* resource);
    void writeCodesysGlobals(XMLElement* resource);
    void writeModel(XMLElement* root);

    const PlcPou* program() const;
    std::string now() const;

    const PlcProject& m_project;
    const Model& m_model;
    const PlcOpenOptions& m_options;
    const bool m_codesys;
    tinyxml2::XMLDocument m_doc;
};

XMLElement* PlcOpenWriter::add(XMLElement* parent, const char* name)
{
    XMLElement* element = m_doc.NewElement(name);
    parent->InsertEndChild(element);
    return element;
}

void PlcOpenWriter::attribute(XMLElement* element, const char* name, std::string_view value)
{
    element->SetAttribute(name, xmlSafeAttribute(value).c_str());
}

// CDATA cannot contain "]]>": the text is cut after "]]" and goes on in a
// second section, which every XML reader joins back.
void PlcOpenWriter::cdata(XMLElement* parent, std::string_view text)
{
    const std::string safe = xmlSafeText(text);
    std::string_view rest = safe;
    for (;;) {
        const std::size_t end = rest.find("]]>");
        const std::string_view piece = end == std::string_view::npos ? rest : rest.substr(0, end + 2);
        tinyxml2::XMLText* node = m_doc.NewText(std::string(piece).c_str());
        node->SetCData(true);
        parent->InsertEndChild(node);
        if (end == std::string_view::npos)
            return;
        rest.remove_prefix(end + 2);
    }
}

// ST bodies and documentation: IEC writes <xhtml:p><![CDATA[...]]></xhtml:p>
// like Beremiz; CODESYS writes <xhtml xmlns="...">escaped text</xhtml> like
// its own exports.
void PlcOpenWriter::formattedText(XMLElement* parent, std::string_view text)
{
    if (m_codesys) {
        XMLElement* xhtml = add(parent, "xhtml");
        attribute(xhtml, "xmlns", kXhtmlNamespace);
        xhtml->InsertEndChild(m_doc.NewText(xmlSafeText(text).c_str()));
        return;
    }
    cdata(add(parent, "xhtml:p"), text);
}

std::string PlcOpenWriter::now() const
{
    return m_options.now ? m_options.now() : currentUtcDateTime();
}

std::string PlcOpenWriter::write()
{
    m_doc.InsertEndChild(m_doc.NewDeclaration());
    XMLElement* root = m_doc.NewElement("project");
    m_doc.InsertEndChild(root);
    attribute(root, "xmlns", m_codesys ? kPlcOpenNamespace200 : kPlcOpenNamespace201);
    if (!m_codesys)
        attribute(root, "xmlns:xhtml", kXhtmlNamespace);

    writeHeaders(root);
    writeTypes(root);
    writeInstances(root);
    writeModel(root);

    tinyxml2::XMLPrinter printer;
    m_doc.Print(&printer);
    std::string text(printer.CStr(), static_cast<std::size_t>(std::max(printer.CStrSize() - 1, 0)));
    if (text.empty() || text.back() != '\n')
        text += '\n';
    return text;
}

void PlcOpenWriter::writeHeaders(XMLElement* root)
{
    const std::string timestamp = now();
    XMLElement* fileHeader = add(root, "fileHeader");
    attribute(fileHeader, "companyName", "GG Studio");
    attribute(fileHeader, "productName", "GG Studio");
    attribute(fileHeader, "productVersion", m_options.productVersion);
    attribute(fileHeader, "creationDateTime", timestamp);

    XMLElement* contentHeader = add(root, "contentHeader");
    attribute(contentHeader, "name", m_project.projectName);
    attribute(contentHeader, "modificationDateTime", timestamp);
    XMLElement* coordinates = add(contentHeader, "coordinateInfo");
    for (const char* language : {"fbd", "ld", "sfc"}) {
        XMLElement* scaling = add(add(coordinates, language), "scaling");
        attribute(scaling, "x", "1");
        attribute(scaling, "y", "1");
    }
}

void PlcOpenWriter::writeTypes(XMLElement* root)
{
    XMLElement* types = add(root, "types");
    add(types, "dataTypes");
    XMLElement* pous = add(types, "pous");
    for (const PlcPou& pou : m_project.pous)
        writePou(pous, pou);
}

void PlcOpenWriter::writePou(XMLElement* pous, const PlcPou& pou)
{
    XMLElement* element = add(pous, "pou");
    attribute(element, "name", pou.name);
    attribute(element, "pouType", pou.kind == PouKind::Program ? "program" : "functionBlock");
    writeInterface(element, pou);
    formattedText(add(add(element, "body"), "ST"), pou.body);
    if (!pou.comment.empty())
        formattedText(add(element, "documentation"), plcOpenDocumentationText(pou.comment));
}

void PlcOpenWriter::writeInterface(XMLElement* pou, const PlcPou& declarations)
{
    XMLElement* interface = add(pou, "interface");
    writeVarList(interface, "inputVars", declarations.inputs);
    writeVarList(interface, "outputVars", declarations.outputs);
    writeVarList(interface, "externalVars", declarations.externals);
    writeVarList(interface, "localVars", declarations.locals);
}

void PlcOpenWriter::writeVarList(XMLElement* parent, const char* listName, const std::vector<PlcVariable>& variables)
{
    if (variables.empty())
        return;
    writeVariables(add(parent, listName), variables);
}

void PlcOpenWriter::writeVariables(XMLElement* list, const std::vector<PlcVariable>& variables)
{
    for (const PlcVariable& variable : variables)
        writeVariable(list, variable);
}

void PlcOpenWriter::writeVariable(XMLElement* list, const PlcVariable& variable)
{
    XMLElement* element = add(list, "variable");
    attribute(element, "name", variable.name);
    XMLElement* type = add(element, "type");
    const std::string typeName = toUpperAscii(variable.typeName);
    if (isElementaryTypeName(typeName)) {
        add(type, typeName.c_str());
    } else {
        attribute(add(type, "derived"), "name", variable.typeName);
    }
    if (!variable.initialValue.empty())
        attribute(add(add(element, "initialValue"), "simpleValue"), "value", variable.initialValue);
    if (!variable.comment.empty())
        formattedText(add(element, "documentation"), plcOpenDocumentationText(variable.comment));
}

const PlcPou* PlcOpenWriter::program() const
{
    auto found = std::find_if(m_project.pous.begin(), m_project.pous.end(),
                              [](const PlcPou& pou) { return pou.kind == PouKind::Program; });
    return found == m_project.pous.end() ? nullptr : &*found;
}

void PlcOpenWriter::writeInstances(XMLElement* root)
{
    XMLElement* configuration = add(add(add(root, "instances"), "configurations"), "configuration");
    attribute(configuration, "name", m_project.configurationName);
    XMLElement* resource = add(configuration, "resource");
    attribute(resource, "name", m_project.resourceName);
    writeTask(resource);
    if (m_codesys) {
        writeCodesysGlobals(resource);
    } else if (!m_project.globals.empty()) {
        // IEC: VAR_GLOBAL of the configuration (an empty VAR_GLOBAL block is
        // refused by some compilers, hence no element without globals).
        writeVariables(add(configuration, "globalVars"), m_project.globals);
    }
}

// IEC tools read the IEC duration and an instance of the program type;
// CODESYS exports the ISO duration, calls the program by its name (programs
// have no instances there) and keeps its own task settings in addData.
void PlcOpenWriter::writeTask(XMLElement* resource)
{
    XMLElement* task = add(resource, "task");
    attribute(task, "name", m_project.taskName);
    attribute(task, "interval", m_codesys ? isoTaskInterval(m_project.cycleTimeMs)
                                          : iecTaskInterval(m_project.cycleTimeMs));
    attribute(task, "priority", std::to_string(std::clamp(m_project.taskPriority, 0, 65535)));
    const PlcPou* gemma = program();
    if (gemma) {
        XMLElement* instance = add(task, "pouInstance");
        attribute(instance, "name", m_codesys ? gemma->name : m_project.programInstanceName);
        attribute(instance, "typeName", m_codesys ? std::string() : gemma->name);
    }
    if (!m_codesys)
        return;
    XMLElement* data = add(add(task, "addData"), "data");
    attribute(data, "name", kCodesysTaskSettingsData);
    attribute(data, "handleUnknown", "implementation");
    XMLElement* settings = add(data, "TaskSettings");
    attribute(settings, "KindOfTask", "Cyclic");
    attribute(settings, "Interval", "t#" + std::to_string(m_project.cycleTimeMs) + "ms");
    attribute(settings, "IntervalUnit", "ms");
    attribute(settings, "WithinSPSTimeSlicing", "true");
}

// The GVL as CODESYS exports it inside the application's resource, with the
// qualified_only attribute that makes the code read GVL.Start.
void PlcOpenWriter::writeCodesysGlobals(XMLElement* resource)
{
    XMLElement* list = add(resource, "globalVars");
    attribute(list, "name", m_project.globalListName.empty() ? "GVL" : m_project.globalListName);
    writeVariables(list, m_project.globals);
    XMLElement* data = add(add(list, "addData"), "data");
    attribute(data, "name", kCodesysAttributesData);
    attribute(data, "handleUnknown", "implementation");
    XMLElement* qualifiedOnly = add(add(data, "Attributes"), "Attribute");
    attribute(qualifiedOnly, "Name", "qualified_only");
    attribute(qualifiedOnly, "Value", "");
}

// The native model travels with the code, so that GG Studio can reopen the
// file; "discard" tells other tools to drop it when they change the project,
// since it would no longer describe it.
void PlcOpenWriter::writeModel(XMLElement* root)
{
    XMLElement* data = add(add(root, "addData"), "data");
    attribute(data, "name", kPlcOpenModelDataName);
    attribute(data, "handleUnknown", "discard");
    XMLElement* model = add(data, std::string(kPlcOpenModelElement).c_str());
    attribute(model, "xmlns:ggstudio", kPlcOpenModelDataName);
    cdata(model, escapeXmlNoncharacters(saveNativeJson(m_model)));
}

} // namespace

// Tools that import the file may write documentation into an ST comment
// (* ... *): as in the generated ST (escapeComment), no "(*" or "*)" of the
// user's survives, while line breaks do.
std::string plcOpenDocumentationText(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if ((text[i] == '(' && next == '*') || (text[i] == '*' && next == ')'))
            out += ' ';
    }
    return out;
}

std::string currentUtcDateTime()
{
    const std::time_t seconds = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char buffer[32];
    const std::size_t length = std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%S", &utc);
    return std::string(buffer, length);
}

std::string iecTaskInterval(int cycleTimeMs)
{
    return "T#" + std::to_string(std::max(cycleTimeMs, 0)) + "ms";
}

std::string isoTaskInterval(int cycleTimeMs)
{
    cycleTimeMs = std::max(cycleTimeMs, 0);
    const int whole = cycleTimeMs / 1000;
    int fraction = cycleTimeMs % 1000;
    std::string text = "PT" + std::to_string(whole);
    if (fraction != 0) {
        std::string digits = std::to_string(fraction);
        digits.insert(0, 3 - digits.size(), '0');
        while (digits.back() == '0')
            digits.pop_back();
        text += "." + digits;
    }
    return text + "S";
}

std::string writePlcOpenXml(const PlcProject& project, const Model& model, const PlcOpenOptions& options)
{
    return PlcOpenWriter(project, model, options).write();
}

} // namespace core
