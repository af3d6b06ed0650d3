#include "samplemodels.h"

#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/model/model.h"
#include "core/verification/property.h"

#include <catch2/catch.hpp>

#include <string>

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
