#include "core/link/modbusmap.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

namespace core::modbusio {

namespace modbusmap {

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
        text.remove_suffix(1);
    return text;
}

struct Field {
    std::string_view text; // trimmed
    int column = 1;        // of the trimmed text's first character
};

std::vector<Field> splitFields(std::string_view line)
{
    std::vector<Field> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        const std::string_view raw = line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                          : comma - start);
        std::size_t lead = 0;
        while (lead < raw.size() && (raw[lead] == ' ' || raw[lead] == '\t'))
            ++lead;
        fields.push_back({trimmed(raw), static_cast<int>(start + lead + 1)});
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }
    return fields;
}

std::string kindText(VariableKind kind, IecType type)
{
    return std::string(type == IecType::Bool ? "a BOOL " : "a numeric ") + std::string(variableKindName(kind));
}

std::uint64_t joinWords(const std::uint16_t* registers, int count)
{
    std::uint64_t bits = 0;
    for (int i = 0; i < count; ++i)
        bits = (bits << 16) | registers[i];
    return bits;
}

std::string rangeProblem(std::string_view shown, IecType type)
{
    const cond::IntegerRange range = cond::integerRange(type);
    return std::string(shown) + " is out of range for " + std::string(iecTypeName(type)) + " ("
         + std::to_string(range.low) + ".." + std::to_string(range.high) + ")";
}

} // namespace modbusmap

std::string_view modbusTableName(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coil: return "coil";
    case ModbusTable::DiscreteInput: return "discrete-input";
    case ModbusTable::HoldingRegister: return "holding-register";
    case ModbusTable::InputRegister: return "input-register";
    }
    return "coil";
}

std::optional<ModbusTable> parseModbusTable(std::string_view name)
{
    for (ModbusTable table : {ModbusTable::Coil, ModbusTable::DiscreteInput, ModbusTable::HoldingRegister,
                              ModbusTable::InputRegister}) {
        if (equalsIgnoreCase(name, modbusTableName(table)))
            return table;
    }
    return std::nullopt;
}

bool isBitTable(ModbusTable table)
{
    return table == ModbusTable::Coil || table == ModbusTable::DiscreteInput;
}

std::optional<ModbusTable> modbusTableFor(VariableKind kind, IecType type, ModbusRole role)
{
    const bool bit = type == IecType::Bool;
    const bool server = role == ModbusRole::Server;
    switch (kind) {
    case VariableKind::Input:
        if (server)
            return bit ? ModbusTable::Coil : ModbusTable::HoldingRegister;
        return bit ? ModbusTable::DiscreteInput : ModbusTable::InputRegister;
    case VariableKind::Output:
        if (server)
            return bit ? ModbusTable::DiscreteInput : ModbusTable::InputRegister;
        return bit ? ModbusTable::Coil : ModbusTable::HoldingRegister;
    case VariableKind::Internal: return std::nullopt;
    }
    return std::nullopt;
}

int modbusWidth(IecType type)
{
    switch (type) {
    case IecType::Dint:
    case IecType::Udint:
    case IecType::Real: return 2;
    case IecType::Lint:
    case IecType::Ulint:
    case IecType::Lreal: return 4;
    default: return 1;
    }
}

const ModbusEntry* ModbusMap::find(std::string_view variable) const
{
    for (const ModbusEntry& entry : entries) {
        if (equalsIgnoreCase(entry.variable, variable))
            return &entry;
    }
    return nullptr;
}

std::vector<const ModbusEntry*> ModbusMap::table(ModbusTable which) const
{
    std::vector<const ModbusEntry*> found;
    for (const ModbusEntry& entry : entries) {
        if (entry.table == which)
            found.push_back(&entry);
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const ModbusEntry* a, const ModbusEntry* b) { return a->address < b->address; });
    return found;
}

ModbusMap defaultModbusMap(const std::vector<Variable>& variables, ModbusRole role)
{
    ModbusMap map;
    map.role = role;
    int next[4] = {0, 0, 0, 0};
    for (const Variable& variable : variables) {
        const std::optional<ModbusTable> table = modbusTableFor(variable.kind, variable.type, role);
        if (!table)
            continue;
        const int width = modbusWidth(variable.type);
        int& address = next[static_cast<int>(*table)];
        if (address + width - 1 > kMaxModbusAddress)
            continue; // a model with more than 65,536 registers of one kind: the rest is not linked
        map.entries.push_back({variable.name, variable.type, variable.kind, *table, address, width});
        address += width;
    }
    return map;
}

std::string ModbusMapError::toString(std::string_view path) const
{
    return std::string(path) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

ModbusMapParse parseModbusMap(std::string_view text, const std::vector<Variable>& variables, ModbusRole role)
{
    using namespace modbusmap;
    ModbusMapParse result;
    result.map.role = role;
    struct Placed {
        std::size_t variable; // index in variables
        ModbusEntry entry;
        int line;
    };
    std::vector<Placed> placed;
    int lineNumber = 0;
    std::size_t start = 0;
    bool sawContent = false;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string_view line =
            text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
        start = end == std::string_view::npos ? text.size() + 1 : end + 1;
        ++lineNumber;
        const std::string_view content = trimmed(line);
        if (content.empty() || content.front() == '#')
            continue;
        std::vector<Field> fields = splitFields(line);
        const bool firstContent = !sawContent;
        sawContent = true;
        if (firstContent && fields.size() == 3 && equalsIgnoreCase(fields[0].text, "variable")
            && equalsIgnoreCase(fields[1].text, "table") && equalsIgnoreCase(fields[2].text, "address"))
            continue;
        if (fields.size() != 3) {
            const int column = fields.size() > 3 ? fields[3].column : static_cast<int>(line.size()) + 1;
            result.errors.push_back({lineNumber, column,
                                     "expected 3 fields (variable,table,address), found "
                                         + std::to_string(fields.size())});
            continue;
        }
        const Field& nameField = fields[0];
        const Field& tableField = fields[1];
        const Field& addressField = fields[2];
        std::size_t index = variables.size();
        for (std::size_t i = 0; i < variables.size(); ++i) {
            if (equalsIgnoreCase(variables[i].name, nameField.text)) {
                index = i;
                break;
            }
        }
        if (index == variables.size()) {
            result.errors.push_back({lineNumber, nameField.column,
                                     "unknown variable '" + std::string(nameField.text) + "'"});
            continue;
        }
        const Variable& variable = variables[index];
        const std::optional<ModbusTable> expected = modbusTableFor(variable.kind, variable.type, role);
        if (!expected) {
            result.errors.push_back({lineNumber, nameField.column,
                                     "'" + variable.name + "' is an internal variable: only inputs and outputs "
                                     "are linked"});
            continue;
        }
        const auto duplicate = std::find_if(placed.begin(), placed.end(),
                                            [&](const Placed& p) { return p.variable == index; });
        if (duplicate != placed.end()) {
            result.errors.push_back({lineNumber, nameField.column,
                                     "'" + variable.name + "' is already mapped on line "
                                         + std::to_string(duplicate->line)});
            continue;
        }
        const std::optional<ModbusTable> table = parseModbusTable(tableField.text);
        if (!table) {
            result.errors.push_back({lineNumber, tableField.column,
                                     "unknown table '" + std::string(tableField.text)
                                         + "' (coil, discrete-input, holding-register or input-register)"});
            continue;
        }
        if (*table != *expected) {
            result.errors.push_back(
                {lineNumber, tableField.column,
                 "'" + variable.name + "' is " + kindText(variable.kind, variable.type) + ": in "
                     + (role == ModbusRole::Server ? "server" : "client") + " mode it goes in the "
                     + std::string(modbusTableName(*expected)) + " table, not " + std::string(modbusTableName(*table))});
            continue;
        }
        long long address = -1;
        const char* first = addressField.text.data();
        const char* last = first + addressField.text.size();
        const auto [ptr, ec] = std::from_chars(first, last, address);
        if (addressField.text.empty() || ec != std::errc() || ptr != last || address < 0
            || address > kMaxModbusAddress) {
            result.errors.push_back({lineNumber, addressField.column,
                                     "address '" + std::string(addressField.text)
                                         + "' is not a number in 0..65535"});
            continue;
        }
        const int width = modbusWidth(variable.type);
        if (address + width - 1 > kMaxModbusAddress) {
            result.errors.push_back({lineNumber, addressField.column,
                                     "'" + variable.name + "' (" + std::string(iecTypeName(variable.type))
                                         + ") takes " + std::to_string(width) + " registers: from "
                                         + std::to_string(address) + " it passes 65535"});
            continue;
        }
        const auto clash = std::find_if(placed.begin(), placed.end(), [&](const Placed& p) {
            return p.entry.table == *table && p.entry.address <= address + width - 1
                && address <= p.entry.address + p.entry.width - 1;
        });
        if (clash != placed.end()) {
            result.errors.push_back({lineNumber, addressField.column,
                                     std::string(modbusTableName(*table)) + " " + std::to_string(address)
                                         + " is already taken by '" + clash->entry.variable + "' (line "
                                         + std::to_string(clash->line) + ")"});
            continue;
        }
        placed.push_back({index, {variable.name, variable.type, variable.kind, *table, static_cast<int>(address), width},
                          lineNumber});
    }
    std::stable_sort(placed.begin(), placed.end(),
                     [](const Placed& a, const Placed& b) { return a.variable < b.variable; });
    for (Placed& p : placed)
        result.map.entries.push_back(std::move(p.entry));
    return result;
}

std::string writeModbusMap(const ModbusMap& map)
{
    std::string text = "variable,table,address\n";
    for (const ModbusEntry& entry : map.entries)
        text += entry.variable + "," + std::string(modbusTableName(entry.table)) + "," + std::to_string(entry.address)
              + "\n";
    return text;
}

std::vector<std::uint16_t> encodeModbusValue(IecType type, const cond::Value& value)
{
    const int width = modbusWidth(type);
    std::uint64_t bits = 0;
    if (type == IecType::Real) {
        const double real = std::holds_alternative<double>(value) ? std::get<double>(value)
                          : std::holds_alternative<std::int64_t>(value) ? static_cast<double>(std::get<std::int64_t>(value))
                                                                         : (std::get<bool>(value) ? 1.0 : 0.0);
        bits = std::bit_cast<std::uint32_t>(static_cast<float>(real));
    } else if (type == IecType::Lreal) {
        const double real = std::holds_alternative<double>(value) ? std::get<double>(value)
                          : std::holds_alternative<std::int64_t>(value) ? static_cast<double>(std::get<std::int64_t>(value))
                                                                         : (std::get<bool>(value) ? 1.0 : 0.0);
        bits = std::bit_cast<std::uint64_t>(real);
    } else {
        std::int64_t integer = 0;
        if (std::holds_alternative<bool>(value))
            integer = std::get<bool>(value) ? 1 : 0;
        else if (std::holds_alternative<std::int64_t>(value))
            integer = std::get<std::int64_t>(value);
        else
            integer = static_cast<std::int64_t>(std::get<double>(value));
        bits = static_cast<std::uint64_t>(integer); // two's complement, cut to the width below
    }
    std::vector<std::uint16_t> registers(static_cast<std::size_t>(width));
    for (int i = width - 1; i >= 0; --i) {
        registers[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(bits & 0xFFFFu);
        bits >>= 16;
    }
    return registers;
}

std::optional<cond::Value> decodeModbusValue(IecType type, const std::uint16_t* registers, std::string& problem)
{
    using namespace modbusmap;
    const std::uint64_t bits = joinWords(registers, modbusWidth(type));
    std::int64_t integer = 0;
    switch (type) {
    case IecType::Bool:
        if (bits > 1) {
            problem = std::to_string(bits) + " is not a BOOL (0 or 1)";
            return std::nullopt;
        }
        return cond::Value(bits == 1);
    case IecType::Real: {
        const double real = std::bit_cast<float>(static_cast<std::uint32_t>(bits));
        if (!std::isfinite(real)) {
            problem = "the REAL is not a finite number";
            return std::nullopt;
        }
        return cond::Value(real);
    }
    case IecType::Lreal: {
        const double real = std::bit_cast<double>(bits);
        if (!std::isfinite(real)) {
            problem = "the LREAL is not a finite number";
            return std::nullopt;
        }
        return cond::Value(real);
    }
    case IecType::Sint:
    case IecType::Int: integer = static_cast<std::int16_t>(bits); break;
    case IecType::Dint: integer = static_cast<std::int32_t>(bits); break;
    case IecType::Lint: integer = static_cast<std::int64_t>(bits); break;
    case IecType::Ulint:
        if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
            problem = rangeProblem(std::to_string(bits), type);
            return std::nullopt;
        }
        integer = static_cast<std::int64_t>(bits);
        break;
    default: integer = static_cast<std::int64_t>(bits); break; // USINT, UINT, UDINT
    }
    const cond::IntegerRange range = cond::integerRange(type);
    if (integer < range.low || integer > range.high) {
        problem = rangeProblem(std::to_string(integer), type);
        return std::nullopt;
    }
    return cond::Value(integer);
}

} // namespace core::modbusio
