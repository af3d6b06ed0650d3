#include "samplemodels.h"

#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stgenerator.h"
#include "core/condition/conditionanalysis.h"
#include "core/formats/gggeneratorformat.h"
#include "core/formats/nativeformat.h"
#include "core/formats/plcopenreader.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/verification/property.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <string>
#include <variant>

namespace test_verificationproperty {

using namespace core;

namespace {

std::string printedBody(const std::string& text)
{
    const ParsedProperty parsed = parseProperty(text);
    INFO(text << ": " << (parsed.error ? parsed.error->message : std::string()));
    REQUIRE(parsed.ok());
    return cond::print(parsed.expression);
}

std::string problemCodes(const Model& model, const std::string& text)
{
    std::string codes;
    for (const PropertyProblem& problem : checkProperty(model, text))
        codes += (codes.empty() ? "" : " ") + problem.code;
    return codes;
}

} // namespace

TEST_CASE("A property is never or always followed by a condition", "[verificationproperty]")
{
    CHECK(parseProperty("never A_Plus AND A_Minus").kind == PropertyKind::Never);
    CHECK(parseProperty("ALWAYS TRUE").kind == PropertyKind::Always);
    CHECK(printedBody("never A AND B") == "A AND B");

    const ParsedProperty missing = parseProperty("sometimes A");
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error->kind == cond::ParseError::Kind::PropertyQuantifier);
    CHECK(missing.error->span.begin == 0);
    CHECK(missing.error->span.end == 9);

    const ParsedProperty blank = parseProperty("   ");
    REQUIRE_FALSE(blank.ok());
    CHECK(blank.error->kind == cond::ParseError::Kind::PropertyQuantifier);

    const ParsedProperty noBody = parseProperty("never ");
    REQUIRE_FALSE(noBody.ok());
    CHECK(noBody.error->kind == cond::ParseError::Kind::OperandAfter);
}

TEST_CASE("Implication binds looser than OR and groups to the right", "[verificationproperty]")
{
    const ParsedProperty parsed = parseProperty("always A OR B -> C -> D");
    REQUIRE(parsed.ok());
    const cond::Node& root = parsed.expression.rootNode();
    REQUIRE(root.kind == cond::NodeKind::Binary);
    CHECK(root.binaryOp == cond::BinaryOp::Implies);
    CHECK(cond::print(parsed.expression, {}) == "A OR B -> C -> D");
    const cond::Node& right = parsed.expression.at(root.right);
    CHECK(right.binaryOp == cond::BinaryOp::Implies);
    const cond::Node& left = parsed.expression.at(root.left);
    CHECK(left.binaryOp == cond::BinaryOp::Or);
    CHECK(printedBody("always (A -> B) -> C") == "(A -> B) -> C");
}

TEST_CASE("State predicates name GEMMA steps and nested steps", "[verificationproperty]")
{
    const ParsedProperty parsed = parseProperty("always in D1 -> NOT F1.X6");
    REQUIRE(parsed.ok());
    int inSteps = 0;
    int nestedSteps = 0;
    for (const cond::Node& node : parsed.expression.nodes) {
        if (node.kind == cond::NodeKind::InStep) {
            ++inSteps;
            CHECK(node.text == "D1");
            CHECK(node.span.begin == 7);
            CHECK(node.span.end == 12);
        }
        if (node.kind == cond::NodeKind::NestedStepActivity) {
            ++nestedSteps;
            CHECK(node.text == "F1");
            CHECK(node.number == 6);
        }
    }
    CHECK(inSteps == 1);
    CHECK(nestedSteps == 1);

    const ParsedProperty noStep = parseProperty("never in (A)");
    REQUIRE_FALSE(noStep.ok());
    CHECK(noStep.error->kind == cond::ParseError::Kind::StepAfterIn);
    CHECK(noStep.error->span.begin == 9);

    // Outside properties `in` and `->` are what they always were.
    CHECK(cond::parse("in AND B").ok());
    CHECK_FALSE(cond::parse("A -> B").ok());
}

TEST_CASE("Checking a property names unknown variables, steps and nested steps", "[verificationproperty]")
{
    const Model model = samples::lampGrafcetModel();
    CHECK(problemCodes(model, "never Lamp AND NOT Start") == "");
    CHECK(problemCodes(model, "always in D1 -> NOT Lamp") == "");
    CHECK(problemCodes(model, "never F1.X3 AND in A1") == "");
    CHECK(problemCodes(model, "never in f1 AND Count > 3") == "");
    CHECK(problemCodes(model, "never Nothing") == property::kUnknownVariable);
    CHECK(problemCodes(model, "never in Z9") == property::kUnknownStep);
    CHECK(problemCodes(model, "never A1.X1") == property::kNoGrafcet);
    CHECK(problemCodes(model, "never F1.X9") == property::kUnknownNestedStep);
    CHECK(problemCodes(model, "never Count + 1") == property::kType);
    CHECK(problemCodes(model, "never (") == property::kSyntax);

    const std::vector<PropertyProblem> problems = checkProperty(model, "never Lamp AND Ghost");
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].span.begin == 15);
    CHECK(problems[0].span.end == 20);
}

TEST_CASE("The model keeps the engineer's properties in order and refuses bad indices", "[verificationproperty]")
{
    Model model;
    int notified = 0;
    model.addObserver([&](const ModelChange& change) {
        if (change.kind == ModelChange::Kind::Properties)
            ++notified;
    });
    REQUIRE(model.addProperty({"never A", "first"}).ok);
    REQUIRE(model.addProperty({"always B", ""}).ok);
    REQUIRE(model.addProperty({"never C", ""}, 0).ok);
    CHECK(model.properties()[0].text == "never C");
    CHECK(model.properties()[1].comment == "first");
    REQUIRE(model.moveProperty(0, 2).ok);
    CHECK(model.properties()[2].text == "never C");
    REQUIRE(model.setPropertyText(1, "always B OR D").ok);
    REQUIRE(model.setPropertyComment(1, "why").ok);
    REQUIRE(model.removeProperty(0).ok);
    CHECK(model.properties().size() == 2);
    CHECK(model.properties()[0].text == "always B OR D");
    CHECK(notified == 7);

    const Model before(model);
    CHECK_FALSE(model.addProperty({"never X", ""}, 5).ok);
    CHECK_FALSE(model.setPropertyText(2, "never X").ok);
    CHECK_FALSE(model.removeProperty(-1).ok);
    CHECK_FALSE(model.moveProperty(0, 9).ok);
    CHECK(model.sameContent(before));
    CHECK(notified == 7);
    CHECK(model.setPropertyText(0, "always B OR D").ok); // unchanged: no notification
    CHECK(notified == 7);
}

TEST_CASE("Properties survive the native file and the PLCopen file, and GG-Generator says it drops them",
          "[verificationproperty]")
{
    Model model = samples::lampGrafcetModel();
    REQUIRE(model.addProperty({"never Lamp AND NOT Start", "the lamp follows the start"}).ok);
    REQUIRE(model.addProperty({"always in D1 -> NOT Lamp", ""}).ok);
    const std::string saved = saveNativeJson(model);
    CHECK(saved.find("\"properties\"") != std::string::npos);
    auto loaded = loadNativeJson(saved, "lamp.json");
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(loaded));
    CHECK(std::get<std::unique_ptr<Model>>(loaded)->sameContent(model));

    const std::string xml = writePlcOpenXml(buildPlcProject(model, Dialect::Iec), model);
    auto fromXml = readPlcOpenModel(xml, "lamp.xml");
    REQUIRE(std::holds_alternative<std::unique_ptr<Model>>(fromXml));
    CHECK(std::get<std::unique_ptr<Model>>(fromXml)->properties() == model.properties());

    const std::vector<GGGeneratorLoss> losses = ggGeneratorLosses(model);
    CHECK(std::any_of(losses.begin(), losses.end(),
                      [](const GGGeneratorLoss& loss) { return loss.kind == GGGeneratorLoss::Kind::Properties; }));

    // A model with properties only still needs format 2.0: an older build refuses it rather than drop them.
    Model plain;
    REQUIRE(plain.addProperty({"never A", ""}).ok);
    CHECK(saveNativeJson(plain).find("\"version\": \"2.0\"") != std::string::npos);
}

TEST_CASE("A malformed properties list is refused with where and what", "[verificationproperty]")
{
    const Model model = samples::lampGrafcetModel();
    std::string saved = saveNativeJson(model);
    const std::string::size_type end = saved.rfind('}');
    auto withProperties = [&](const std::string& list) {
        return saved.substr(0, end) + ",\n  \"properties\": " + list + "\n}\n";
    };
    const std::vector<std::pair<std::string, std::string>> cases{
        {"{}", "/properties"},
        {"[1]", "/properties/0"},
        {"[{\"comment\": \"x\"}]", "/properties/0/text"},
        {"[{\"text\": 3}]", "/properties/0/text"},
        {"[{\"text\": \"never A\", \"colour\": \"red\"}]", "/properties/0/colour"},
    };
    for (const auto& [list, where] : cases) {
        INFO(list);
        auto loaded = loadNativeJson(withProperties(list), "bad.json");
        REQUIRE(std::holds_alternative<LoadError>(loaded));
        CHECK(std::get<LoadError>(loaded).toString().find(where) != std::string::npos);
    }
}

TEST_CASE("A wrong nested step is named for what is wrong, step 0 included", "[verificationproperty]")
{
    const Model model = samples::lampGrafcetModel();
    const auto firstMessage = [&](const std::string& text) {
        const std::vector<PropertyProblem> problems = checkProperty(model, text);
        REQUIRE_FALSE(problems.empty());
        return problems.front().code + ": " + problems.front().message;
    };
    // X0 used to be read as a qualified name ("qualified names are not allowed").
    CHECK(firstMessage("never F1.X0") == "GP005: the GRAFCET of F1 has no step 0");
    CHECK(firstMessage("never f1.x0 AND Lamp") == "GP005: the GRAFCET of F1 has no step 0");
    CHECK(firstMessage("never A1.X0") == "GP004: the step A1 has no nested GRAFCET");
    CHECK(firstMessage("never Z9.X0") == "GP003: there is no visible GEMMA step 'Z9'");
    CHECK(firstMessage("never F1.X12") == "GP005: the GRAFCET of F1 has no step 12");
    // Not a step activity at all: still refused by the parser.
    CHECK(problemCodes(model, "never F1.Lamp") == property::kSyntax);
}

} // namespace test_verificationproperty
