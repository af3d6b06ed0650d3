#include "modelfactory.h"

#include "core/formats/nativeformat.h"
#include "core/formats/plcopenreader.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <variant>

TEST_CASE("Load + save the realistic model (target <= 2 ms)", "[benchmark][files]")
{
    const std::string text = core::saveNativeJson(factory::realisticModel());
    BENCHMARK("load + save native JSON")
    {
        auto loaded = core::loadNativeJson(text, "<bench>");
        return core::saveNativeJson(*std::get<std::unique_ptr<core::Model>>(loaded)).size();
    };
}

// tinyxml2 alone took 155 s on this file (it is quadratic in the attributes of
// one element); the reader refuses it after the well-formedness check.
TEST_CASE("Read a 2.3 MB PLCopen file with 200000 attributes on one element (target <= 1 s)", "[benchmark][files]")
{
    std::string xml = "<?xml version=\"1.0\"?>\n<project";
    for (int i = 0; i < 200000; ++i)
        xml += " a" + std::to_string(i) + "=\"v\"";
    xml += "/>\n";
    BENCHMARK("read PLCopen XML, 200,000 attributes on one element")
    {
        auto loaded = core::readPlcOpenModel(xml, "<bench>");
        return std::holds_alternative<core::LoadError>(loaded);
    };
}
