// Reopening a PLCopen file GG Studio exported: what the loader says when the
// file's code no longer is the code its embedded model generates, when the
// file carries two models, and that the embedded model comes back exactly
// whatever text the user typed (issue #32: nothing lost, nothing changed
// behind the user's back).

#include "filetestsupport.h"
#include "hostilemodels.h"
#include "samplemodels.h"

#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"
#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace test_plcopenloadwarnings {

using namespace core;

namespace {

PlcOpenOptions fixedClock()
{
    PlcOpenOptions options;
    options.now = [] { return std::string("2026-11-21T10:00:00"); };
    return options;
}

std::string exported(const Model& model, Dialect dialect)
{
    return writePlcOpenXml(buildPlcProject(model, dialect), model, fixedClock());
}

std::vector<std::string> warningTexts(const LoadedModel& loaded)
{
    std::vector<std::string> texts;
    for (const LoadWarning& warning : loaded.warnings)
        texts.push_back(warning.toString());
    return texts;
}

// "line L, column C" of a byte offset, counted here rather than by the code under test.
std::string positionOf(const std::string& text, std::size_t offset)
{
    std::size_t line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(offset - lineStart + 1);
}

Model drillingCell()
{
    const LoadedModel loaded =
        loadModelFile((std::filesystem::path(GGSTUDIO_EXAMPLES_DIR) / "drilling-cell.ggstudio.json").string());
    REQUIRE(loaded.ok());
    return *loaded.model;
}

} // namespace

TEST_CASE("A PLCopen file whose code is the exported code opens without a warning", "[plcopen][loadwarnings]")
{
    std::vector<Model> models{Model(), samples::caseStudyModel(), drillingCell()};
    for (std::uint32_t seed = 0; seed < 10; ++seed) {
        models.push_back(samples::randomModel(seed));
        // Through a native file first: a model only holds valid UTF-8 (every
        // loader checks it, the editor's text is Unicode), while the hostile
        // models hold invalid bytes, which no file can carry.
        const LoadedModel hostile = loadModelText(saveNativeJson(samples::hostileModel(seed)), "hostile.json");
        REQUIRE(hostile.ok());
        models.push_back(*hostile.model);
    }
    for (const Model& model : models) {
        for (const Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
            const LoadedModel loaded = loadModelText(exported(model, dialect), "machine.xml");
            REQUIRE(loaded.ok());
            CHECK(warningTexts(loaded) == std::vector<std::string>{});
        }
    }
    // A tool that saves the file with CR LF line ends changes nothing an XML
    // reader sees.
    std::string crlf;
    for (const char c : exported(samples::caseStudyModel(), Dialect::Iec))
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const LoadedModel loaded = loadModelText(crlf, "machine.xml");
    REQUIRE(loaded.ok());
    CHECK(loaded.warnings.empty());
}

TEST_CASE("Code edited outside GG Studio is named, and the embedded model is used", "[plcopen][loadwarnings]")
{
    // It used to open from the embedded model without a word: the edit was lost.
    const Model model = samples::caseStudyModel();
    for (const Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        std::string xml = exported(model, dialect);
        const std::size_t gemma = xml.find("<pou name=\"GEMMA\"");
        REQUIRE(gemma != std::string::npos);
        const std::size_t condition = xml.find("IF ", gemma);
        const std::size_t then = xml.find(" THEN", condition);
        REQUIRE(then != std::string::npos);
        xml.replace(condition, then - condition, "IF TRUE");

        const LoadedModel loaded = loadModelText(xml, "machine.xml");
        REQUIRE(loaded.ok());
        CHECK(loaded.model->sameContent(model));
        CHECK(warningTexts(loaded) == std::vector<std::string>{
            "machine.xml: " + positionOf(xml, gemma)
            + ": warning: the code of POU GEMMA differs from the code the embedded model generates: the embedded "
              "model is used; the edits to the code are not kept"});
    }
}

TEST_CASE("Edited declarations, globals and POUs are named too", "[plcopen][loadwarnings]")
{
    const Model model = samples::caseStudyModel();
    std::string xml = exported(model, Dialect::Iec);
    // An initial value changed in the configuration's globals.
    const std::size_t globals = xml.find("<globalVars");
    REQUIRE(globals != std::string::npos);
    const std::size_t variable = xml.find("<variable name=\"", globals);
    REQUIRE(variable != std::string::npos);
    xml.insert(variable + std::string("<variable name=\"").size(), "Renamed");
    // A function block removed, another one added.
    const std::size_t fb = xml.find("<pou name=\"", xml.find("<pou name=\"GEMMA\"") + 1);
    REQUIRE(fb != std::string::npos);
    const std::size_t fbEnd = xml.find("</pou>", fb) + std::string("</pou>").size();
    const std::string fbName = xml.substr(fb + 11, xml.find('"', fb + 11) - fb - 11);
    xml.replace(fb, fbEnd - fb, "<pou name=\"Mine\" pouType=\"function\"/>");
    // The cycle time changed in the task.
    const std::string interval = "interval=\"" + iecTaskInterval(model.settings().cycleTimeMs) + "\"";
    const std::size_t task = xml.find(interval);
    REQUIRE(task != std::string::npos);
    xml.replace(task, interval.size(), "interval=\"T#1s\"");
    const std::size_t mine = xml.find("<pou name=\"Mine\"");
    const std::size_t pous = xml.find("<pous>");
    const std::size_t globalsNow = xml.find("<globalVars");

    const LoadedModel loaded = loadModelText(xml, "machine.xml");
    REQUIRE(loaded.ok());
    CHECK(loaded.model->sameContent(model));
    CHECK(warningTexts(loaded) == std::vector<std::string>{
        "machine.xml: " + positionOf(xml, mine)
            + ": warning: the POU Mine is not one the embedded model generates: the embedded model is used; this POU "
              "is not kept",
        "machine.xml: " + positionOf(xml, pous) + ": warning: the POU " + fbName
            + " that the embedded model generates is missing from the file: the embedded model is used and generates "
              "it again",
        "machine.xml: " + positionOf(xml, globalsNow)
            + ": warning: the global variables differ from those the embedded model generates: the embedded model is "
              "used; the edits to the code are not kept",
        "machine.xml: " + positionOf(xml, xml.rfind("<task", task))
            + ": warning: the task differs from the one the embedded model generates (MainTask, interval "
            + iecTaskInterval(model.settings().cycleTimeMs)
            + ", priority 1): the embedded model is used; the edits to the code are not kept"});

    // A documentation edited in the interface counts too.
    std::string documented = exported(model, Dialect::Iec);
    const std::size_t documentation = documented.find("<documentation>", documented.find("<variable"));
    REQUIRE(documentation != std::string::npos);
    const std::size_t text = documented.find("CDATA[", documentation) + 6;
    documented.insert(text, "edited: ");
    const LoadedModel edited = loadModelText(documented, "machine.xml");
    REQUIRE(edited.ok());
    CHECK(edited.warnings.size() == 1);
}

TEST_CASE("A PLCopen file with two embedded models is refused where the second is", "[plcopen][loadwarnings]")
{
    // The first used to win, silently.
    const Model first = samples::caseStudyModel();
    std::string xml = exported(first, Dialect::Iec);
    const std::string second = "<addData><data name=\"urn:ggstudio:model:1\" handleUnknown=\"discard\"><m><![CDATA["
                               + saveNativeJson(Model()) + "]]></m></data></addData>\n";
    xml.insert(xml.rfind("</project>"), second);
    const LoadedModel loaded = loadModelText(xml, "twice.xml");
    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error.toString()
          == "twice.xml: " + positionOf(xml, xml.find("<m>")) + ": a second GG Studio model (the first is at "
                 + positionOf(xml, xml.find("<ggstudio:model"))
                 + "): GG Studio cannot tell which one the file means, so it opens neither");

    // All on one line, and two models in one entry: the column still says which.
    const std::string json = "<![CDATA[" + saveNativeJson(Model()) + "]]>";
    const std::string oneLine = "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><addData>"
                                "<data name=\"urn:ggstudio:model:1\" handleUnknown=\"discard\"><m>" + json + "</m>"
                                "<m>" + json + "</m></data></addData></project>";
    const LoadedModel refused = loadModelText(oneLine, "line.xml");
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error.location == positionOf(oneLine, oneLine.find("<m>", oneLine.find("<m>") + 1)));
}

TEST_CASE("Every string the model accepts survives the PLCopen round trip", "[plcopen][loadwarnings]")
{
    // U+FFFE and U+FFFF used to come back as U+FFFD: XML 1.0 cannot carry
    // them, nor the C0 controls other than tab, line feed and carriage return.
    std::string awkward("nul\0", 4);
    for (char c = 1; c < 0x20; ++c)
        awkward += c;
    awkward += "\x7F \xC2\x80 \xC2\x9F \xED\x9F\xBF \xEE\x80\x80 \xEF\xB7\x90 \xEF\xBF\xBD \xEF\xBF\xBE \xEF\xBF\xBF"
               " \xF0\x90\x80\x80 \xF0\x9F\xBF\xBE \xF4\x8F\xBF\xBF ]]> </x> &amp; \r\n \r end";
    Model model = drillingCell();
    REQUIRE(model.setName(awkward));
    REQUIRE(model.setStepComment("A1", awkward));
    REQUIRE(model.setCondition(model.transitions().front().id, awkward));
    REQUIRE(model.setVariableComment(model.variables().front().name, awkward));
    REQUIRE(model.addVariable({"x" + awkward, IecType::Int, awkward, awkward}));
    REQUIRE(model.addProperty({awkward, awkward}));
    const Grafcet* grafcet = model.grafcet("F1");
    REQUIRE(grafcet);
    REQUIRE(model.setGrafcetStepComment("F1", grafcet->steps().front().number, awkward));
    REQUIRE(model.setReceptivity("F1", grafcet->transitions().front().number, awkward));
    REQUIRE(model.addGrafcetAction("F1", grafcet->steps().front().number, {ActionTiming::Continuous, awkward}));

    for (const Dialect dialect : {Dialect::Iec, Dialect::Codesys}) {
        const std::string xml = exported(model, dialect);
        const LoadedModel loaded = loadModelText(xml, "awkward.xml");
        REQUIRE(loaded.ok());
        CHECK(loaded.model->sameContent(model));
        CHECK(saveNativeJson(*loaded.model) == saveNativeJson(model));
        CHECK(loaded.warnings.empty());
    }
}

TEST_CASE("POUs the model does not generate are named up to ten, then counted", "[plcopen][loadwarnings]")
{
    // Each warning's position costs a pass over the text: a file of many
    // POUs, all on one line, must not take quadratic time.
    const Model model = samples::caseStudyModel();
    std::string xml = exported(model, Dialect::Iec);
    std::string strangers;
    for (int i = 0; i < 20000; ++i)
        strangers += "<pou name=\"Extra" + std::to_string(i) + "\" pouType=\"function\"/>";
    const std::size_t pousEnd = xml.find("</pous>");
    REQUIRE(pousEnd != std::string::npos);
    xml.insert(pousEnd, strangers);
    const LoadedModel loaded = loadModelText(xml, "many.xml");
    REQUIRE(loaded.ok());
    REQUIRE(loaded.warnings.size() == 11);
    CHECK(loaded.warnings[9].message
          == "the POU Extra9 is not one the embedded model generates: the embedded model is used; this POU is not kept");
    CHECK(loaded.warnings[10].location == positionOf(xml, xml.find("<pou name=\"Extra10\"")));
    CHECK(loaded.warnings[10].message
          == "19990 more POUs from here on are not ones the embedded model generates: the embedded model is used; "
             "they are not kept");
}

} // namespace test_plcopenloadwarnings
