#include "samplemodels.h"

#include "core/checks.h"
#include "core/modelfiles.h"
#include "core/nativeformat.h"
#include "core/plcopenreader.h"
#include "core/plcopenwriter.h"
#include "core/stgenerator.h"
#include "core/xmltext.h"

#include <catch2/catch.hpp>
#include <tinyxml2.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace core;
using tinyxml2::XMLElement;

namespace {

const std::string kClock = "2026-11-21T10:00:00";

PlcOpenOptions fixedClock(const std::string& timestamp = kClock)
{
    PlcOpenOptions options;
    options.now = [timestamp] { return timestamp; };
    options.productVersion = "9.8.7";
    return options;
}

// A project as the generator would build it, written by hand so that these
// tests do not depend on the generator.
PlcProject handProject(Dialect dialect)
{
    PlcProject project;
    project.projectName = "Line <3> & \"press\"";
    project.dialect = dialect;
    project.globalListName = dialect == Dialect::Codesys ? "GVL" : "";
    project.globals = {{"Start", "BOOL", "", "start <button> & ]]> done"}, {"Level", "INT", "5", ""}};
    PlcPou gemma;
    gemma.name = "GEMMA";
    gemma.kind = PouKind::Program;
    gemma.locals = {{"State", "UINT", "6", ""}, {"Entry", "BOOL", "TRUE", ""}, {"F1", "F1_FB", "", "nested"}};
    if (dialect == Dialect::Iec)
        gemma.externals = {{"Start", "BOOL", "", ""}, {"Level", "INT", "", ""}};
    const std::string start = dialect == Dialect::Codesys ? "GVL.Start" : "Start";
    gemma.body = "CASE State OF\n    6: (* A6 a ]]> b <c> & d *)\n        IF " + start +
                 " AND 1 < 2 THEN\n            State := 8;\n        END_IF;\nEND_CASE;";
    gemma.comment = "the GEMMA layer";
    PlcPou fb;
    fb.name = "F1_FB";
    fb.kind = PouKind::FunctionBlock;
    fb.inputs = {{"Initialization", "BOOL", "", ""}};
    fb.outputs = {{"Complete", "BOOL", "", ""}};
    fb.body = "IF Initialization THEN\n    Complete := FALSE;\nEND_IF;\nComplete := TRUE;";
    project.pous = {gemma, fb};
    project.cycleTimeMs = 20;
    return project;
}

struct ParsedXml {
    tinyxml2::XMLDocument document;
    explicit ParsedXml(const std::string& text) { REQUIRE(document.Parse(text.c_str(), text.size()) == tinyxml2::XML_SUCCESS); }
    const XMLElement* root() const { return document.RootElement(); }
};

const XMLElement* child(const XMLElement* parent, const char* name)
{
    REQUIRE(parent != nullptr);
    const XMLElement* element = parent->FirstChildElement(name);
    INFO("element <" << parent->Name() << "> has no child <" << name << ">");
    REQUIRE(element != nullptr);
    return element;
}

const XMLElement* path(const XMLElement* element, std::initializer_list<const char*> names)
{
    for (const char* name : names)
        element = child(element, name);
    return element;
}

std::vector<std::string> childNames(const XMLElement* parent)
{
    std::vector<std::string> names;
    for (const XMLElement* e = parent->FirstChildElement(); e; e = e->NextSiblingElement())
        names.emplace_back(e->Name());
    return names;
}

std::string joinedText(const XMLElement* element, bool* allCData = nullptr)
{
    std::string text;
    if (allCData)
        *allCData = true;
    for (const tinyxml2::XMLNode* node = element->FirstChild(); node; node = node->NextSibling()) {
        if (const tinyxml2::XMLText* piece = node->ToText()) {
            text += piece->Value();
            if (allCData && !piece->CData())
                *allCData = false;
        }
    }
    return text;
}

const XMLElement* pouNamed(const XMLElement* root, const std::string& name)
{
    for (const XMLElement* pou = path(root, {"types", "pous"})->FirstChildElement("pou"); pou;
         pou = pou->NextSiblingElement("pou")) {
        if (name == pou->Attribute("name"))
            return pou;
    }
    FAIL("no POU " << name);
    return nullptr;
}

const XMLElement* variableNamed(const XMLElement* list, const std::string& name)
{
    for (const XMLElement* v = list->FirstChildElement("variable"); v; v = v->NextSiblingElement("variable")) {
        if (name == v->Attribute("name"))
            return v;
    }
    FAIL("no variable " << name);
    return nullptr;
}

std::string attr(const XMLElement* element, const char* name)
{
    const char* value = element->Attribute(name);
    return value ? value : "<absent>";
}

std::filesystem::path scratchFile(const std::string& name)
{
    const auto folder = std::filesystem::temp_directory_path() / ("ggstudio-plcopen-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    return folder / name;
}

// Runs xmllint on the text; CODESYS files are checked against the v2.01
// schema after the namespace swap (their structure is the same).
bool validatesAgainstSchema(std::string text, const std::string& fileName)
{
    const std::string from(kPlcOpenNamespace200);
    if (const std::size_t at = text.find(from); at != std::string::npos)
        text.replace(at, from.size(), std::string(kPlcOpenNamespace201));
    const auto file = scratchFile(fileName);
    std::ofstream(file, std::ios::binary) << text;
    const std::string command = "xmllint --noout --nonet --schema '" GGSTUDIO_REFERENCE_DIR
                                "/plcopen/tc6_xml_v201.xsd' '" + file.string() + "' 2>'" + file.string() + ".log'";
    const int status = std::system(command.c_str());
    if (status != 0) {
        std::ifstream log(file.string() + ".log");
        std::string line;
        while (std::getline(log, line))
            UNSCOPED_INFO(line);
    }
    return status == 0;
}

} // namespace

TEST_CASE("IEC PLCopen XML has the TC6 v2.01 structure", "[plcopen]")
{
    const PlcProject project = handProject(Dialect::Iec);
    ParsedXml xml(writePlcOpenXml(project, Model(), fixedClock()));
    const XMLElement* root = xml.root();
    CHECK(std::string(root->Name()) == "project");
    CHECK(attr(root, "xmlns") == "http://www.plcopen.org/xml/tc6_0201");
    CHECK(attr(root, "xmlns:xhtml") == "http://www.w3.org/1999/xhtml");
    CHECK(childNames(root) == std::vector<std::string>{"fileHeader", "contentHeader", "types", "instances", "addData"});

    const XMLElement* fileHeader = child(root, "fileHeader");
    CHECK(attr(fileHeader, "companyName") == "GG Studio");
    CHECK(attr(fileHeader, "productName") == "GG Studio");
    CHECK(attr(fileHeader, "productVersion") == "9.8.7");
    CHECK(attr(fileHeader, "creationDateTime") == kClock);
    const XMLElement* contentHeader = child(root, "contentHeader");
    CHECK(attr(contentHeader, "name") == project.projectName);
    CHECK(attr(contentHeader, "modificationDateTime") == kClock);
    for (const char* language : {"fbd", "ld", "sfc"}) {
        const XMLElement* scaling = path(contentHeader, {"coordinateInfo", language, "scaling"});
        CHECK(attr(scaling, "x") == "1");
        CHECK(attr(scaling, "y") == "1");
    }

    CHECK(childNames(child(root, "types")) == std::vector<std::string>{"dataTypes", "pous"});
    CHECK(child(path(root, {"types"}), "dataTypes")->FirstChildElement() == nullptr);

    const XMLElement* gemma = pouNamed(root, "GEMMA");
    CHECK(attr(gemma, "pouType") == "program");
    CHECK(childNames(gemma) == std::vector<std::string>{"interface", "body", "documentation"});
    const XMLElement* interface = child(gemma, "interface");
    CHECK(childNames(interface) == std::vector<std::string>{"externalVars", "localVars"});
    const XMLElement* state = variableNamed(child(interface, "localVars"), "State");
    CHECK(child(state, "type")->FirstChildElement("UINT") != nullptr);
    CHECK(attr(path(state, {"initialValue", "simpleValue"}), "value") == "6");
    const XMLElement* instance = variableNamed(child(interface, "localVars"), "F1");
    CHECK(attr(path(instance, {"type", "derived"}), "name") == "F1_FB");
    CHECK(joinedText(path(instance, {"documentation", "xhtml:p"})) == "nested");
    CHECK(variableNamed(child(interface, "externalVars"), "Level")->FirstChildElement("initialValue") == nullptr);

    bool allCData = false;
    CHECK(joinedText(path(gemma, {"body", "ST", "xhtml:p"}), &allCData) == project.pous[0].body);
    CHECK(allCData);
    CHECK(joinedText(path(gemma, {"documentation", "xhtml:p"})) == "the GEMMA layer");

    const XMLElement* fb = pouNamed(root, "F1_FB");
    CHECK(attr(fb, "pouType") == "functionBlock");
    CHECK(childNames(child(fb, "interface")) == std::vector<std::string>{"inputVars", "outputVars"});
    CHECK(joinedText(path(fb, {"body", "ST", "xhtml:p"})) == project.pous[1].body);

    const XMLElement* configuration = path(root, {"instances", "configurations", "configuration"});
    CHECK(attr(configuration, "name") == "GemmaConfiguration");
    CHECK(childNames(configuration) == std::vector<std::string>{"resource", "globalVars"});
    const XMLElement* resource = child(configuration, "resource");
    CHECK(attr(resource, "name") == "GemmaResource");
    const XMLElement* task = child(resource, "task");
    CHECK(attr(task, "name") == "MainTask");
    CHECK(attr(task, "interval") == "T#20ms");
    CHECK(attr(task, "priority") == "1");
    CHECK(attr(child(task, "pouInstance"), "name") == "GemmaInstance");
    CHECK(attr(child(task, "pouInstance"), "typeName") == "GEMMA");
    const XMLElement* globals = child(configuration, "globalVars");
    CHECK(attr(path(variableNamed(globals, "Level"), {"initialValue", "simpleValue"}), "value") == "5");
    CHECK(joinedText(path(variableNamed(globals, "Start"), {"documentation", "xhtml:p"}))
          == "start <button> & ]]> done");

    const XMLElement* data = path(root, {"addData", "data"});
    CHECK(attr(data, "name") == "urn:ggstudio:model:1");
    CHECK(attr(data, "handleUnknown") == "discard");
    CHECK(child(data, "ggstudio:model") != nullptr);
}

TEST_CASE("IEC PLCopen XML without globals has no empty VAR_GLOBAL", "[plcopen]")
{
    PlcProject project = handProject(Dialect::Iec);
    project.globals.clear();
    project.cycleTimeMs = 1500;
    project.taskPriority = 70000;
    ParsedXml xml(writePlcOpenXml(project, Model(), fixedClock()));
    const XMLElement* configuration = path(xml.root(), {"instances", "configurations", "configuration"});
    CHECK(childNames(configuration) == std::vector<std::string>{"resource"});
    const XMLElement* task = path(configuration, {"resource", "task"});
    CHECK(attr(task, "interval") == "T#1500ms");
    CHECK(attr(task, "priority") == "65535"); // the schema's upper bound
}

TEST_CASE("PLCopen XML validates against the TC6 v2.01 schema", "[plcopen]")
{
    PlcProject iec = handProject(Dialect::Iec);
    CHECK(validatesAgainstSchema(writePlcOpenXml(iec, Model(), fixedClock()), "hand-iec.xml"));
    iec.globals.clear();
    iec.pous.clear();
    CHECK(validatesAgainstSchema(writePlcOpenXml(iec, Model(), fixedClock()), "empty-iec.xml"));
    // CODESYS writes tc6_0200, whose schema is not here; its element order is the same.
    const PlcProject codesys = handProject(Dialect::Codesys);
    CHECK(validatesAgainstSchema(writePlcOpenXml(codesys, Model(), fixedClock()), "hand-codesys.xml"));
}

TEST_CASE("PLCopen XML carries any user text intact or safely replaced", "[plcopen]")
{
    PlcProject project = handProject(Dialect::Iec);
    project.pous[0].body = "]]>start ]]]]>> (* x ]]> y *) ]]";
    project.pous[0].comment = std::string("bell\x07 nul-free \x1B escape and bad \xFF byte");
    const std::string text = writePlcOpenXml(project, Model(), fixedClock());
    ParsedXml xml(text);
    const XMLElement* gemma = pouNamed(xml.root(), "GEMMA");
    CHECK(joinedText(path(gemma, {"body", "ST", "xhtml:p"})) == project.pous[0].body);
    CHECK(joinedText(path(gemma, {"documentation", "xhtml:p"}))
          == "bell\xEF\xBF\xBD nul-free \xEF\xBF\xBD escape and bad \xEF\xBF\xBD byte");
    CHECK(validatesAgainstSchema(text, "awkward-iec.xml"));
}

TEST_CASE("Same model and same clock give the same bytes", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const PlcProject project = handProject(Dialect::Iec);
    const std::string first = writePlcOpenXml(project, model, fixedClock());
    CHECK(first == writePlcOpenXml(project, model, fixedClock()));
    std::string later = writePlcOpenXml(project, model, fixedClock("2027-01-02T03:04:05"));
    CHECK(later != first);
    std::size_t at = 0;
    while ((at = later.find("2027-01-02T03:04:05", at)) != std::string::npos)
        later.replace(at, kClock.size(), kClock);
    CHECK(later == first);
}

TEST_CASE("The default clock writes the current UTC time as xs:dateTime", "[plcopen]")
{
    const std::string now = currentUtcDateTime();
    REQUIRE(now.size() == 19);
    CHECK(now[4] == '-');
    CHECK(now[10] == 'T');
    CHECK(now[13] == ':');
    CHECK(now.substr(0, 2) == "20");
    ParsedXml xml(writePlcOpenXml(handProject(Dialect::Iec), Model(), PlcOpenOptions()));
    CHECK(attr(child(xml.root(), "fileHeader"), "productVersion") == GGSTUDIO_VERSION);
    CHECK(attr(child(xml.root(), "fileHeader"), "creationDateTime").size() == 19);
}

TEST_CASE("CODESYS PLCopen XML follows what CODESYS V3.5 exports", "[plcopen]")
{
    const PlcProject project = handProject(Dialect::Codesys);
    ParsedXml xml(writePlcOpenXml(project, Model(), fixedClock()));
    const XMLElement* root = xml.root();
    CHECK(attr(root, "xmlns") == "http://www.plcopen.org/xml/tc6_0200");
    CHECK(root->Attribute("xmlns:xhtml") == nullptr);

    const XMLElement* gemma = pouNamed(root, "GEMMA");
    const XMLElement* xhtml = path(gemma, {"body", "ST", "xhtml"});
    CHECK(attr(xhtml, "xmlns") == "http://www.w3.org/1999/xhtml");
    bool allCData = true;
    CHECK(joinedText(xhtml, &allCData) == project.pous[0].body);
    CHECK_FALSE(allCData); // escaped text, as CODESYS writes it
    CHECK(joinedText(xhtml).find("IF GVL.Start AND") != std::string::npos);
    CHECK(gemma->FirstChildElement("interface")->FirstChildElement("externalVars") == nullptr);

    const XMLElement* resource = path(root, {"instances", "configurations", "configuration", "resource"});
    CHECK(childNames(resource) == std::vector<std::string>{"task", "globalVars"});
    const XMLElement* task = child(resource, "task");
    CHECK(attr(task, "interval") == "PT0.02S");
    CHECK(attr(child(task, "pouInstance"), "name") == "GEMMA");
    CHECK(attr(child(task, "pouInstance"), "typeName") == "");
    const XMLElement* settings = path(task, {"addData", "data", "TaskSettings"});
    CHECK(attr(settings, "KindOfTask") == "Cyclic");
    CHECK(attr(settings, "Interval") == "t#20ms");

    const XMLElement* gvl = child(resource, "globalVars");
    CHECK(attr(gvl, "name") == "GVL");
    CHECK(attr(path(variableNamed(gvl, "Level"), {"initialValue", "simpleValue"}), "value") == "5");
    CHECK(joinedText(path(variableNamed(gvl, "Start"), {"documentation", "xhtml"})) == "start <button> & ]]> done");
    const XMLElement* data = path(gvl, {"addData", "data"});
    CHECK(attr(data, "name") == "http://www.3s-software.com/plcopenxml/attributes");
    const XMLElement* attribute = path(data, {"Attributes", "Attribute"});
    CHECK(attr(attribute, "Name") == "qualified_only");
    CHECK(attr(attribute, "Value") == "");

    CHECK(attr(path(root, {"addData", "data"}), "name") == "urn:ggstudio:model:1");
}

TEST_CASE("Task intervals in IEC and ISO 8601 notation", "[plcopen]")
{
    CHECK(iecTaskInterval(20) == "T#20ms");
    CHECK(iecTaskInterval(1) == "T#1ms");
    CHECK(isoTaskInterval(20) == "PT0.02S");
    CHECK(isoTaskInterval(5) == "PT0.005S");
    CHECK(isoTaskInterval(100) == "PT0.1S");
    CHECK(isoTaskInterval(1000) == "PT1S");
    CHECK(isoTaskInterval(1500) == "PT1.5S");
    CHECK(isoTaskInterval(3600000) == "PT3600S");
    CHECK(isoTaskInterval(-3) == "PT0S");
}

TEST_CASE("Text is made fit for XML 1.0", "[plcopen]")
{
    CHECK(xmlSafeText("plain <text> & \"more\"\n\ttab") == "plain <text> & \"more\"\n\ttab");
    CHECK(xmlSafeText("caf\xC3\xA9 \xF0\x9F\x98\x80") == "caf\xC3\xA9 \xF0\x9F\x98\x80");
    CHECK(xmlSafeText(std::string("a\0b", 3)) == "a\xEF\xBF\xBD" "b");
    CHECK(xmlSafeText("\x01\x1F\x7F") == "\xEF\xBF\xBD\xEF\xBF\xBD\x7F");
    CHECK(xmlSafeText("\xC0\xAF") == "\xEF\xBF\xBD\xEF\xBF\xBD");         // overlong '/'
    CHECK(xmlSafeText("\xED\xA0\x80") == "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD"); // surrogate
    CHECK(xmlSafeText("\xEF\xBF\xBE") == "\xEF\xBF\xBD");                 // U+FFFE
    CHECK(xmlSafeText("cut \xE2\x82") == "cut \xEF\xBF\xBD\xEF\xBF\xBD");
    CHECK(xmlSafeAttribute("two\nlines\tand\rtab") == "two lines and tab");
}

TEST_CASE("A PLCopen file GG Studio wrote opens as the same model", "[plcopen]")
{
    for (const Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        const Model model = samples::caseStudyModel();
        const std::string xml = writePlcOpenXml(buildPlcProject(model, dialect), model, fixedClock());
        auto loaded = readPlcOpenModel(xml, "machine.xml");
        REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
        CHECK(std::get<std::unique_ptr<Model>>(loaded)->sameContent(model));
    }
}

TEST_CASE("Random models survive the PLCopen round trip", "[plcopen]")
{
    for (std::uint32_t seed = 0; seed < 25; ++seed) {
        const Model model = samples::randomModel(seed);
        INFO("seed " << seed);
        const std::string xml = writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model, fixedClock());
        auto loaded = readPlcOpenModel(xml, "random.xml");
        REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
        CHECK(std::get<std::unique_ptr<Model>>(loaded)->sameContent(model));
    }
}

TEST_CASE("The embedded model is found whatever the PLCopen prefix", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const std::string json = saveNativeJson(model);
    const std::string xml = "<?xml version=\"1.0\"?>\n<ppx:project xmlns:ppx=\"http://www.plcopen.org/xml/tc6_0201\">"
                            "<ppx:addData><ppx:data name=\"other\" handleUnknown=\"preserve\"><x/></ppx:data>"
                            "<ppx:data name=\"urn:ggstudio:model:1\" handleUnknown=\"discard\"><m>"
                            + json + "</m></ppx:data></ppx:addData></ppx:project>";
    auto loaded = readPlcOpenModel(xml, "prefixed.xml");
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
    CHECK(std::get<std::unique_ptr<Model>>(loaded)->sameContent(model));
}

TEST_CASE("Reading a PLCopen file says clearly what is wrong", "[plcopen]")
{
    auto errorOf = [](const std::string& xml) {
        auto loaded = readPlcOpenModel(xml, "bad.xml");
        REQUIRE(std::holds_alternative<LoadError>(loaded));
        const LoadError error = std::get<LoadError>(loaded);
        CHECK(error.file == "bad.xml");
        return error;
    };
    SECTION("malformed XML gives the line")
    {
        const LoadError unclosed = errorOf("<?xml version=\"1.0\"?>\n<project>\n  <types>\n</project>\n");
        CHECK(unclosed.location == "line 3"); // where the unclosed element starts
        CHECK(unclosed.message == "not well-formed XML: an element is not closed by its matching end tag");
        const LoadError attribute = errorOf("<project>\n\n<types a=1/></project>");
        CHECK(attribute.location == "line 3");
        CHECK(attribute.message.find("not well-formed XML") != std::string::npos);
    }
    SECTION("empty text")
    {
        CHECK(errorOf("").message.find("no XML element") != std::string::npos);
    }
    SECTION("another XML document")
    {
        const LoadError error = errorOf("<?xml version=\"1.0\"?>\n<svg width=\"3\"/>");
        CHECK(error.message.find("not a PLCopen XML file") != std::string::npos);
        CHECK(error.message.find("<svg>") != std::string::npos);
    }
    SECTION("a PLCopen file from another tool")
    {
        const LoadError error = errorOf("<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><fileHeader/>"
                                        "<addData><data name=\"http://www.3s-software.com/plcopenxml/projectstructure\" "
                                        "handleUnknown=\"discard\"><ProjectStructure/></data></addData></project>");
        CHECK(error.message.find("a PLCopen file without a GG Studio model: GG Studio can only open PLCopen files "
                                 "it exported")
              != std::string::npos);
    }
    SECTION("a damaged embedded model")
    {
        const LoadError error = errorOf("<project><addData><data name=\"urn:ggstudio:model:1\" handleUnknown=\"discard\">"
                                        "<ggstudio:model><![CDATA[{\"format\": ]]></ggstudio:model></data></addData>"
                                        "</project>");
        CHECK(error.location.rfind("embedded model", 0) == 0);
        CHECK(error.message.find("the GG Studio model inside this PLCopen file is invalid") != std::string::npos);
    }
}

TEST_CASE("Generated projects export to schema-valid PLCopen XML", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const std::string iec = writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model, fixedClock());
    CHECK(validatesAgainstSchema(iec, "realistic-iec.xml"));
    const std::string codesys = writePlcOpenXml(buildPlcProject(model, Dialect::Codesys), model, fixedClock());
    CHECK(validatesAgainstSchema(codesys, "realistic-codesys.xml"));
    ParsedXml xml(codesys);
    const std::string body = joinedText(path(pouNamed(xml.root(), "GEMMA"), {"body", "ST", "xhtml"}));
    CHECK(body.find("GVL.Start") != std::string::npos);
    CHECK(body.find("Stop_F1_3_MEM") != std::string::npos);
    // Every FB of a visible macro/enclosing step, and no other.
    for (const char* fb : {"F1_FB", "F2_FB", "F3_FB", "F4_FB", "F5_FB", "D3_FB"})
        CHECK(attr(pouNamed(xml.root(), fb), "pouType") == "functionBlock");
    CHECK(std::string(codesys).find("\"F6_FB\"") == std::string::npos);
    CHECK(std::string(codesys).find("\"A7_FB\"") == std::string::npos);
}

TEST_CASE("PLCopen XML of the realistic model is fast", "[plcopen][performance]")
{
    const Model model = samples::caseStudyModel();
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    auto fastest = std::chrono::nanoseconds::max();
    for (int run = 0; run < 20; ++run) {
        const auto start = std::chrono::steady_clock::now();
        const std::string xml = writePlcOpenXml(project, model, fixedClock());
        fastest = std::min(fastest, std::chrono::steady_clock::now() - start);
        REQUIRE(!xml.empty());
    }
#ifdef NDEBUG
    const auto budget = std::chrono::milliseconds(3);
#else
    const auto budget = std::chrono::milliseconds(15); // unoptimised build
#endif
    const double milliseconds = std::chrono::duration<double, std::milli>(fastest).count();
    INFO("fastest of 20: " << milliseconds << " ms");
    CHECK(fastest <= budget);
}

TEST_CASE("The random sample models are valid and varied", "[plcopen]")
{
    int hiddenSteps = 0, hiddenTransitions = 0, tokens = 0, negated = 0, enclosing = 0;
    for (std::uint32_t seed = 0; seed < 200; ++seed) {
        const Model model = samples::randomModel(seed);
        INFO("seed " << seed);
        REQUIRE_FALSE(hasErrors(checkModel(model)));
        for (const Step& step : model.steps()) {
            hiddenSteps += step.hidden ? 1 : 0;
            enclosing += step.type == StepType::Enclosing ? 1 : 0;
        }
        for (const Transition& t : model.transitions()) {
            hiddenTransitions += t.hidden ? 1 : 0;
            tokens += static_cast<int>(t.tokens.size());
            negated += t.negated ? 1 : 0;
        }
    }
    CHECK(samples::randomModel(7).sameContent(samples::randomModel(7)));
    CHECK_FALSE(samples::randomModel(7).sameContent(samples::randomModel(8)));
    CHECK(hiddenSteps > 100);
    CHECK(hiddenTransitions > 100);
    CHECK(tokens > 200);
    CHECK(negated > 200);
    CHECK(enclosing > 200);
}

TEST_CASE("Model files of PLCopen XML are recognised and opened", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const std::string xml = "\xEF\xBB\xBF" + writePlcOpenXml(buildPlcProject(model, Dialect::Codesys), model, fixedClock());
    const LoadedModel loaded = loadModelText(xml, "machine.xml");
    CHECK(loaded.format == ModelFormat::PlcOpen);
    REQUIRE(loaded.ok());
    CHECK(loaded.model->sameContent(model));

    const LoadedModel foreign = loadModelText("<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\"/>", "other.xml");
    CHECK(foreign.format == ModelFormat::PlcOpen);
    CHECK_FALSE(foreign.ok());
    CHECK(foreign.error.toString().find("other.xml: a PLCopen file without a GG Studio model") == 0);
}
