#include "hostilemodels.h"
#include "samplemodels.h"

#include "core/checks/checks.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"
#include "core/formats/plcopenreader.h"
#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/xmltext.h"

#include <catch2/catch.hpp>
#include <tinyxml2.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <string>
#include <unistd.h>
#include <vector>

namespace test_plcopen {

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
    SECTION("malformed XML gives the line and column")
    {
        const LoadError unclosed = errorOf("<?xml version=\"1.0\"?>\n<project>\n  <types>\n</project>\n");
        CHECK(unclosed.location == "line 4, column 1"); // the end tag that does not match
        CHECK(unclosed.message == "not well-formed XML: an element is not closed by its matching end tag: "
                                  "</project> here closes <types> of line 3, column 3");
        const LoadError attribute = errorOf("<project>\n\n<types a=1/></project>");
        CHECK(attribute.location == "line 3, column 10");
        CHECK(attribute.message == "not well-formed XML: the value of the attribute 'a' is not quoted");
        const LoadError unfinished = errorOf("<project>\n  <types>");
        CHECK(unfinished.location == "line 2, column 3");
        CHECK(unfinished.message == "not well-formed XML: the element <types> is not closed");
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

namespace {

std::string exportedFile()
{
    const Model model = samples::caseStudyModel();
    return writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model, fixedClock());
}

// An exported file with the fragment added as the last child of <project>.
std::string exportedFileWithChild(const std::string& fragment)
{
    std::string xml = exportedFile();
    const std::size_t end = xml.rfind("</project>");
    REQUIRE(end != std::string::npos);
    return xml.insert(end, fragment);
}

LoadError readError(const std::string& xml)
{
    auto loaded = readPlcOpenModel(xml, "bad.xml");
    REQUIRE(std::holds_alternative<LoadError>(loaded));
    return std::get<LoadError>(loaded);
}

} // namespace

TEST_CASE("Character references that are no XML character are refused where they are", "[plcopen]")
{
    const LoadError nul = readError("<project>\n  <a>&#0;</a>\n</project>");
    CHECK(nul.location == "line 2, column 6");
    CHECK(nul.message == "not well-formed XML: the character reference &#0; stands for U+0000 (NUL), "
                         "which XML 1.0 cannot carry");
    const LoadError control = readError("<project a=\"x&#1;\"/>");
    CHECK(control.location == "line 1, column 14");
    CHECK(control.message == "not well-formed XML: the character reference &#1; stands for U+0001, "
                             "which XML 1.0 cannot carry");
    const LoadError nonCharacter = readError("<project>&#xFFFE;</project>");
    CHECK(nonCharacter.location == "line 1, column 10");
    CHECK(nonCharacter.message == "not well-formed XML: the character reference &#xFFFE; stands for U+FFFE, "
                                  "which XML 1.0 cannot carry");
    const LoadError surrogate = readError("<project>\n&#xD800;</project>");
    CHECK(surrogate.location == "line 2, column 1");
    CHECK(surrogate.message == "not well-formed XML: the character reference &#xD800; stands for U+D800, "
                               "a surrogate, which XML 1.0 cannot carry");
    const LoadError beyond = readError("<project>&#x110000;</project>");
    CHECK(beyond.location == "line 1, column 10");
    CHECK(beyond.message == "not well-formed XML: the character reference &#x110000; is beyond U+10FFFF, "
                            "the last Unicode character");
    const LoadError huge = readError("<project>&#99999999999999999999999999;</project>");
    CHECK(huge.message.find("is beyond U+10FFFF") != std::string::npos);
    // In an exported file the reference is refused, not turned into nothing.
    CHECK(readError(exportedFileWithChild("<documentation>&#0;</documentation>")).message.find("&#0;")
          != std::string::npos);
}

TEST_CASE("A raw NUL byte is refused where it is", "[plcopen]")
{
    const LoadError error = readError(std::string("<project>\n<a>x\0</a></project>", 26));
    CHECK(error.location == "line 2, column 5");
    CHECK(error.message == "not well-formed XML: a NUL byte (U+0000), which XML 1.0 cannot carry");
    std::string exported = exportedFile();
    exported.insert(exported.find("<types>"), 1, '\0');
    CHECK(readError(exported).message.find("a NUL byte") != std::string::npos);
}

TEST_CASE("A PLCopen file has exactly one root element", "[plcopen]")
{
    const LoadError second = readError(exportedFile() + "<project/>\n");
    CHECK(second.message == "not well-formed XML: a second root element <project>: "
                            "an XML file has exactly one root element");
    const LoadError small = readError("<project/>\n  <other/>");
    CHECK(small.location == "line 2, column 3");
    const LoadError text = readError("<project/>\nmore");
    CHECK(text.location == "line 2, column 1");
    CHECK(text.message == "not well-formed XML: text after the root element");
}

TEST_CASE("Entities are neither declared nor expanded", "[plcopen]")
{
    SECTION("an undeclared entity")
    {
        const LoadError error = readError("<project>\n  <a>&foo;</a></project>");
        CHECK(error.location == "line 2, column 6");
        CHECK(error.message == "not well-formed XML: the entity &foo; is not declared "
                               "(XML predefines only &lt; &gt; &amp; &apos; &quot;)");
        CHECK(readError(exportedFileWithChild("<documentation>&foo;</documentation>")).message.find("&foo;")
              != std::string::npos);
    }
    SECTION("a raw '&'")
    {
        const LoadError inText = readError("<project>R&D</project>");
        CHECK(inText.location == "line 1, column 11");
        CHECK(inText.message == "not well-formed XML: a '&' that starts no reference (write it as &amp;)");
        const LoadError inAttribute = readError("<project a=\"x & y\"/>");
        CHECK(inAttribute.location == "line 1, column 15");
        CHECK(readError("<project>&amp</project>").message
              == "not well-formed XML: the reference &amp is not closed by ';'");
    }
    SECTION("billion laughs")
    {
        const std::string laughs = "<?xml version=\"1.0\"?>\n"
                                   "<!DOCTYPE project [\n"
                                   "  <!ENTITY lol \"lol\">\n"
                                   "  <!ENTITY lol2 \"&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;\">\n"
                                   "  <!ENTITY lol3 \"&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;\">\n"
                                   "]>\n<project>&lol3;</project>";
        const LoadError error = readError(laughs);
        CHECK(error.location == "line 2, column 1");
        CHECK(error.message == "not well-formed XML: a DOCTYPE: GG Studio reads no document type "
                               "declaration and expands no entity (PLCopen files have none)");
    }
    SECTION("an external entity")
    {
        const std::string external = "<!DOCTYPE project [<!ENTITY secret SYSTEM \"file:///etc/passwd\">]>"
                                     "<project>&secret;</project>";
        const LoadError error = readError(external);
        CHECK(error.location == "line 1, column 1");
        CHECK(error.message.find("a DOCTYPE") != std::string::npos);
        CHECK(error.message.find("root:") == std::string::npos);
    }
    SECTION("well-formed references are read")
    {
        const std::string xml
            = exportedFileWithChild("<documentation a=\"&#233;&lt;\">&#x1F600;&#65;&amp;&lt;&gt;&apos;&quot;&#x10FFFF;"
                                    "</documentation>");
        auto loaded = readPlcOpenModel(xml, "references.xml");
        REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
        CHECK(std::get<std::unique_ptr<Model>>(loaded)->sameContent(samples::caseStudyModel()));
    }
}

TEST_CASE("An element with very many attributes is refused, not read for minutes", "[plcopen]")
{
    auto withAttributes = [](int count) {
        std::string xml = "<?xml version=\"1.0\"?>\n<project";
        for (int i = 0; i < count; ++i)
            xml += " a" + std::to_string(i) + "=\"v\"";
        return xml + "/>\n";
    };
    const LoadError justOver = readError(withAttributes(33));
    CHECK(justOver.location == "line 2, column 256");
    CHECK(justOver.message == "not well-formed XML: the element <project> has more than 32 attributes "
                              "(GG Studio reads at most 32 on one element)");
    const std::string huge = withAttributes(200000);
    CHECK(huge.size() > 2'200'000);
    CHECK(readError(huge).message == justOver.message);
    const LoadError duplicate = readError("<project a=\"1\" b=\"2\" a=\"3\"/>");
    CHECK(duplicate.location == "line 1, column 22");
    CHECK(duplicate.message == "not well-formed XML: the attribute 'a' appears twice in <project>");
}

namespace {

// Every element of the document, depth first.
void forEachElement(const XMLElement* element, const std::function<void(const XMLElement*)>& visit)
{
    visit(element);
    for (const XMLElement* c = element->FirstChildElement(); c; c = c->NextSiblingElement())
        forEachElement(c, visit);
}

// The ST text with its (* *) comments removed; fails on a comment left open.
std::string stCode(const std::string& text)
{
    std::string code;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find("(*", at);
        code += text.substr(at, open == std::string::npos ? std::string::npos : open - at);
        if (open == std::string::npos)
            break;
        const std::size_t close = text.find("*)", open + 2);
        REQUIRE(close != std::string::npos);
        at = close + 2;
    }
    return code;
}

} // namespace

TEST_CASE("PLCopen XML of models with hostile user text declares only identifiers", "[plcopen][property]")
{
    const std::regex identifier("[A-Za-z_][A-Za-z0-9_]*");
    const std::regex literal("TRUE|FALSE|[-+]?[0-9][0-9_]*(\\.[0-9][0-9_]*)?([eE][-+]?[0-9_]+)?");
    for (std::uint32_t seed = 1; seed <= 60; ++seed) {
        INFO("hostile model " << seed);
        const Model model = samples::hostileModel(seed);
        for (Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
            const std::string xml = writePlcOpenXml(buildPlcProject(model, dialect), model, fixedClock());
            ParsedXml parsed(xml);
            forEachElement(parsed.root(), [&](const XMLElement* element) {
                const std::string name = element->Name();
                if (name == "variable") {
                    const std::string declared = attr(element, "name");
                    INFO("variable " << declared);
                    CHECK(std::regex_match(declared, identifier));
                    CHECK_FALSE(isIecKeyword(declared));
                } else if (name == "simpleValue") {
                    CHECK(std::regex_match(attr(element, "value"), literal));
                } else if (name == "documentation") {
                    const std::string text = joinedText(element->FirstChildElement());
                    INFO("documentation " << text);
                    CHECK(text.find("(*") == std::string::npos);
                    CHECK(text.find("*)") == std::string::npos);
                } else if (name == "ST") {
                    const std::string code = stCode(joinedText(element->FirstChildElement()));
                    CHECK(code.find(samples::kInjectedMarker) == std::string::npos);
                }
            });
        }
    }
    // The schema holds as well (xmllint is slow: a few of them).
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        const Model model = samples::hostileModel(seed);
        CHECK(validatesAgainstSchema(writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model, fixedClock()),
                                     "hostile-" + std::to_string(seed) + ".xml"));
    }
}

TEST_CASE("Documentation keeps no comment delimiter of the user's", "[plcopen]")
{
    Model model;
    REQUIRE(model.addVariable({"Start", IecType::Bool, "", "button *) Injected := 1; (* S1\nsecond line"}));
    REQUIRE(model.setStepComment("F1", "fills (*) bottles *)"));
    REQUIRE(model.setStepType("F1", StepType::Macro));
    const std::string xml = writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model, fixedClock());
    ParsedXml parsed(xml);
    const XMLElement* globals = path(parsed.root(), {"instances", "configurations", "configuration", "globalVars"});
    CHECK(joinedText(path(variableNamed(globals, "Start"), {"documentation", "xhtml:p"}))
          == "button * ) Injected := 1; ( * S1\nsecond line");
    CHECK(joinedText(path(pouNamed(parsed.root(), "F1_FB"), {"documentation", "xhtml:p"}))
          == "Nested behaviour of F1 Normal production (macro-step): fills ( * ) bottles * )");
}

TEST_CASE("The well-formedness check refuses what XML 1.0 refuses, at the first wrong byte", "[plcopen]")
{
    struct Case {
        std::string text;
        std::size_t offset;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"", 0, "the file holds no XML element"},
        {"  \n", 3, "the file holds no XML element"},
        {"<?xml version=\"1.0\"?><!-- only a comment -->", 44, "the file holds no XML element"},
        {"hello<project/>", 0, "text before the root element"},
        {"<project/><!-- fine --><?pi fine?>\n<", 35, "markup after the root element"},
        {"<project>\x01</project>", 9, "the character U+0001, which XML 1.0 cannot carry"},
        {"<project>\xEF\xBF\xBF</project>", 9, "the character U+FFFF, which XML 1.0 cannot carry"},
        {"<project>\xC3</project>", 9, "invalid UTF-8 (GG Studio reads PLCopen files in UTF-8)"},
        {" <?xml version=\"1.0\"?><project/>", 1, "an XML declaration that is not at the very start of the file"},
        {"<?xml version=\"1.1\"?><project/>", 0, "XML version '1.1' is not read: GG Studio reads XML 1.0"},
        {"<?xml encoding=\"UTF-8\"?><project/>", 0, "the XML declaration does not start with its version"},
        {"<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><project/>", 0,
         "the encoding 'ISO-8859-1': GG Studio reads PLCopen files in UTF-8"},
        {"<?xml version=\"1.0\" standalone=\"maybe\"?><project/>", 0,
         "standalone must be 'yes' or 'no' in the XML declaration"},
        {"<?xml version=\"1.0\"encoding=\"UTF-8\"?><project/>", 19, "expected a space or '?>' in the XML declaration"},
        {"<project><!-- a -- b --></project>", 16, "'--' inside a comment"},
        {"<project><!-- open", 9, "a comment is not closed by '-->'"},
        {"<project><![CDATA[ open", 9, "a CDATA section is not closed by ']]>'"},
        {"<project>a ]]> b</project>", 11, "']]>' in text (write it as ]]&gt;)"},
        {"<project>1 < 2</project>", 11, "a '<' that starts no markup (write it as &lt;)"},
        {"<project a=\"1 < 2\"/>", 14, "a '<' in the value of the attribute 'a' (write it as &lt;)"},
        {"<project a=\"1\"b=\"2\"/>", 14, "expected a space, '>' or '/>' in the start tag <project>"},
        {"<project a/>", 10, "expected '=' after the attribute 'a'"},
        {"<project a=\"open/>", 9, "the value of the attribute 'a' is not closed by \""},
        {"<project a=\"1\"", 0, "the start tag <project> is not closed by '>'"},
        {"<project 1=\"1\"/>", 9, "expected an attribute name, '>' or '/>' in the start tag <project>"},
        {"<project></project >x", 20, "text after the root element"},
        {"<project></project", 18, "expected '>' to close the end tag </project>"},
        {"<project><a></b></project>", 12,
         "an element is not closed by its matching end tag: </b> here closes <a> of line 1, column 10"},
        {"<project>&#;</project>", 9, "a malformed character reference: expected digits and ';' after '&#'"},
        {"<project>&#x12</project>", 9,
         "a malformed character reference: expected hexadecimal digits and ';' after '&#x'"},
        {"<project>&# 65;</project>", 9, "a malformed character reference: expected digits and ';' after '&#'"},
        {"<project><?xml version=\"1.0\"?></project>", 9,
         "an XML declaration that is not at the very start of the file"},
        {"<project><!DOCTYPE x></project>", 9, "a '<' that starts no markup (write it as &lt;)"},
        {"<project><!ENTITY x \"y\"></project>", 9, "a '<' that starts no markup (write it as &lt;)"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const XmlCheck check = checkWellFormedXml(c.text);
        REQUIRE(check.problem.has_value());
        CHECK(check.problem->offset == c.offset);
        CHECK(check.problem->message == c.message);
    }
}

TEST_CASE("The well-formedness check accepts what XML 1.0 allows", "[plcopen]")
{
    const std::vector<std::string> wellFormed = {
        "<project/>",
        "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"utf-8\" standalone='yes' ?>\r\n<project/>\n",
        "<?xml version=\"1.0\"?>\n<!-- a - comment --><?target data?><ppx:project xmlns:ppx=\"urn:x\">"
        "<ppx:a b = 'x\"y' c=\"it's &gt; &#x41;\">text &amp; more > fine ]] ]><![CDATA[<&]]]]><!-- c --><?p?>"
        "</ppx:a   ></ppx:project>  <!-- after --> \n",
        "<caf\xC3\xA9 \xC3\xA9t\xC3\xA9=\"\xE2\x82\xAC\">\xF0\x9F\x98\x80&#x10FFFF;&#xFFFD;&#9;&#10;&#13;</caf\xC3\xA9>",
    };
    for (const std::string& text : wellFormed) {
        INFO(text);
        const XmlCheck check = checkWellFormedXml(text);
        CHECK_FALSE(check.problem.has_value());
        if (check.problem)
            INFO(check.problem->message);
    }
    CHECK(checkWellFormedXml("<?xml version=\"1.0\"?>\n<project/>").rootOffset == 22);

    // Nesting: as deep as kMaxXmlDepth reads, one level more is refused at its start tag.
    auto nested = [](std::size_t depth) {
        std::string open, close;
        for (std::size_t i = 0; i < depth; ++i)
            open += "<e>", close += "</e>";
        return open + close;
    };
    CHECK_FALSE(checkWellFormedXml(nested(kMaxXmlDepth)).problem.has_value());
    const XmlCheck tooDeep = checkWellFormedXml(nested(kMaxXmlDepth + 1));
    REQUIRE(tooDeep.problem.has_value());
    CHECK(tooDeep.problem->offset == 3 * kMaxXmlDepth);
    CHECK(tooDeep.problem->message == "elements nested deeper than 64 levels");
    CHECK(checkWellFormedXml("<project>&#" + std::string(100000, '9') + ";</project>").problem->message
          == "the character reference &#" + std::string(38, '9')
                 + "... is beyond U+10FFFF, the last Unicode character");
}

} // namespace test_plcopen
