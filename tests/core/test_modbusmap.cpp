#include "core/link/modbusmap.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace test_modbusmap {

using namespace core;
using namespace core::modbusio;

std::vector<Variable> sampleVariables()
{
    return {
        {"Start", IecType::Bool, "", "", VariableKind::Input},
        {"Speed", IecType::Int, "", "", VariableKind::Input},
        {"Motor", IecType::Bool, "", "", VariableKind::Output},
        {"Count", IecType::Dint, "", "", VariableKind::Output},
        {"Memo", IecType::Bool, "", "", VariableKind::Internal},
        {"Stop", IecType::Bool, "", "", VariableKind::Input},
        {"Level", IecType::Real, "", "", VariableKind::Input},
        {"Lamp", IecType::Bool, "", "", VariableKind::Output},
    };
}

TEST_CASE("The default map numbers each table from 0 in declaration order", "[modbusmap]")
{
    const ModbusMap map = defaultModbusMap(sampleVariables(), ModbusRole::Server);
    REQUIRE(map.entries.size() == 7); // Memo is internal
    CHECK(map.find("Memo") == nullptr);
    CHECK(map.find("start")->table == ModbusTable::Coil);
    CHECK(map.find("Start")->address == 0);
    CHECK(map.find("Stop")->address == 1);
    CHECK(map.find("Speed")->table == ModbusTable::HoldingRegister);
    CHECK(map.find("Speed")->address == 0);
    CHECK(map.find("Level")->address == 1); // after Speed's one register
    CHECK(map.find("Level")->width == 2);
    CHECK(map.find("Motor")->table == ModbusTable::DiscreteInput);
    CHECK(map.find("Lamp")->address == 1);
    CHECK(map.find("Count")->table == ModbusTable::InputRegister);
    CHECK(map.find("Count")->width == 2);
    const auto coils = map.table(ModbusTable::Coil);
    REQUIRE(coils.size() == 2);
    CHECK(coils[0]->variable == "Start");
}

TEST_CASE("In client mode the tables flip", "[modbusmap]")
{
    const ModbusMap map = defaultModbusMap(sampleVariables(), ModbusRole::Client);
    CHECK(map.find("Start")->table == ModbusTable::DiscreteInput);
    CHECK(map.find("Speed")->table == ModbusTable::InputRegister);
    CHECK(map.find("Motor")->table == ModbusTable::Coil);
    CHECK(map.find("Count")->table == ModbusTable::HoldingRegister);
}

TEST_CASE("A written map reads back the same", "[modbusmap]")
{
    const ModbusMap map = defaultModbusMap(sampleVariables(), ModbusRole::Server);
    const std::string text = writeModbusMap(map);
    CHECK(text.rfind("variable,table,address\nStart,coil,0\nSpeed,holding-register,0\n", 0) == 0);
    const ModbusMapParse parsed = parseModbusMap(text, sampleVariables(), ModbusRole::Server);
    REQUIRE(parsed.ok());
    REQUIRE(parsed.map.entries.size() == map.entries.size());
    for (std::size_t i = 0; i < map.entries.size(); ++i) {
        CHECK(parsed.map.entries[i].variable == map.entries[i].variable);
        CHECK(parsed.map.entries[i].table == map.entries[i].table);
        CHECK(parsed.map.entries[i].address == map.entries[i].address);
    }
}

TEST_CASE("A CSV map may name a subset, with comments, blanks and spaces", "[modbusmap]")
{
    const ModbusMapParse parsed = parseModbusMap("# my twin\n\n  start , COIL , 100\r\nMotor,discrete-input,7\n",
                                                 sampleVariables(), ModbusRole::Server);
    REQUIRE(parsed.ok());
    REQUIRE(parsed.map.entries.size() == 2);
    CHECK(parsed.map.entries[0].variable == "Start"); // spelled as declared
    CHECK(parsed.map.entries[0].address == 100);
    CHECK(parsed.map.find("Motor")->address == 7);
    CHECK(parsed.map.find("Stop") == nullptr);
}

TEST_CASE("A CSV map's errors give their line, column and what is wrong", "[modbusmap]")
{
    const auto firstError = [](std::string_view text, ModbusRole role = ModbusRole::Server) {
        const ModbusMapParse parsed = parseModbusMap(text, sampleVariables(), role);
        REQUIRE_FALSE(parsed.ok());
        return parsed.errors.front().toString("map.csv");
    };
    CHECK(firstError("Start,coil\n") == "map.csv:1:11: expected 3 fields (variable,table,address), found 2");
    CHECK(firstError("Start,coil,1,2\n") == "map.csv:1:14: expected 3 fields (variable,table,address), found 4");
    CHECK(firstError("\nGhost,coil,1\n") == "map.csv:2:1: unknown variable 'Ghost'");
    CHECK(firstError("Memo,coil,1\n") == "map.csv:1:1: 'Memo' is an internal variable: only inputs and outputs are linked");
    CHECK(firstError("Start,coil,1\nStart,coil,2\n") == "map.csv:2:1: 'Start' is already mapped on line 1");
    CHECK(firstError("Start, bits ,1\n") == "map.csv:1:8: unknown table 'bits' (coil, discrete-input, "
                                             "holding-register or input-register)");
    CHECK(firstError("Start,holding-register,1\n")
          == "map.csv:1:7: 'Start' is a BOOL input: in server mode it goes in the coil table, not holding-register");
    CHECK(firstError("Speed,coil,1\n", ModbusRole::Client)
          == "map.csv:1:7: 'Speed' is a numeric input: in client mode it goes in the input-register table, not coil");
    CHECK(firstError("Start,coil,65536\n") == "map.csv:1:12: address '65536' is not a number in 0..65535");
    CHECK(firstError("Start,coil,-1\n") == "map.csv:1:12: address '-1' is not a number in 0..65535");
    CHECK(firstError("Start,coil,1x\n") == "map.csv:1:12: address '1x' is not a number in 0..65535");
    CHECK(firstError("Start,coil,\n") == "map.csv:1:12: address '' is not a number in 0..65535");
    CHECK(firstError("Level,holding-register,65535\n")
          == "map.csv:1:24: 'Level' (REAL) takes 2 registers: from 65535 it passes 65535");
    CHECK(firstError("Start,coil,3\nStop,coil,3\n") == "map.csv:2:11: coil 3 is already taken by 'Start' (line 1)");
    // Level takes 10 and 11: Speed at 11 overlaps it.
    CHECK(firstError("Level,holding-register,10\nSpeed,holding-register,11\n")
          == "map.csv:2:24: holding-register 11 is already taken by 'Level' (line 1)");
    // The same address in another table is no clash; every error is listed.
    const ModbusMapParse parsed =
        parseModbusMap("Start,coil,0\nMotor,discrete-input,0\nGhost,coil,1\nStop,coil,0\n", sampleVariables(),
                       ModbusRole::Server);
    REQUIRE(parsed.errors.size() == 2);
    CHECK(parsed.errors[0].line == 3);
    CHECK(parsed.errors[1].line == 4);
}

TEST_CASE("Values travel as registers, most significant word first", "[modbusmap]")
{
    CHECK(encodeModbusValue(IecType::Int, cond::Value(std::int64_t{-2})) == std::vector<std::uint16_t>{0xFFFE});
    CHECK(encodeModbusValue(IecType::Dint, cond::Value(std::int64_t{0x12345678}))
          == std::vector<std::uint16_t>{0x1234, 0x5678});
    CHECK(encodeModbusValue(IecType::Real, cond::Value(1.0)) == std::vector<std::uint16_t>{0x3F80, 0x0000});
    CHECK(encodeModbusValue(IecType::Bool, cond::Value(true)) == std::vector<std::uint16_t>{1});
    CHECK(encodeModbusValue(IecType::Lint, cond::Value(std::int64_t{-1}))
          == std::vector<std::uint16_t>{0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF});
    for (IecType type : allIecTypes()) {
        const cond::Value value = type == IecType::Bool ? cond::Value(true)
                                : isRealType(type)      ? cond::Value(2.5)
                                                        : cond::Value(std::int64_t{cond::integerRange(type).high});
        const std::vector<std::uint16_t> registers = encodeModbusValue(type, value);
        REQUIRE(registers.size() == static_cast<std::size_t>(modbusWidth(type)));
        std::string problem;
        const std::optional<cond::Value> back = decodeModbusValue(type, registers.data(), problem);
        INFO(iecTypeName(type));
        REQUIRE(back);
        CHECK(*back == value);
        CHECK(problem.empty());
    }
}

TEST_CASE("Registers that hold no value of the type are refused with a reason", "[modbusmap]")
{
    std::string problem;
    const std::uint16_t big[] = {300};
    CHECK_FALSE(decodeModbusValue(IecType::Usint, big, problem));
    CHECK(problem == "300 is out of range for USINT (0..255)");
    const std::uint16_t minus[] = {0xFF00}; // -256
    CHECK_FALSE(decodeModbusValue(IecType::Sint, minus, problem));
    CHECK(problem == "-256 is out of range for SINT (-128..127)");
    const std::uint16_t nan[] = {0x7FC0, 0};
    CHECK_FALSE(decodeModbusValue(IecType::Real, nan, problem));
    CHECK(problem == "the REAL is not a finite number");
    const std::uint16_t huge[] = {0x8000, 0, 0, 0};
    CHECK_FALSE(decodeModbusValue(IecType::Ulint, huge, problem));
    const std::uint16_t two[] = {2};
    CHECK_FALSE(decodeModbusValue(IecType::Bool, two, problem));
    CHECK(problem == "2 is not a BOOL (0 or 1)");
    const std::uint16_t minusOne[] = {0xFFFF};
    CHECK(decodeModbusValue(IecType::Int, minusOne, problem) == cond::Value(std::int64_t{-1}));
    CHECK(decodeModbusValue(IecType::Uint, minusOne, problem) == cond::Value(std::int64_t{65535}));
}

} // namespace test_modbusmap
