#pragma once

// Which model variable sits at which Modbus table and address, for the
// simulator's Modbus TCP link (docs/modbus.md). Plain C++: the transport
// (Qt SerialBus) lives in editor/modbus.
//
// The simulator is a Modbus server (the default) or a client of a twin that
// is itself the server; the tables follow the role:
//
//                      server (twin writes/reads us)   client (we read/write the twin)
//   BOOL input         coil (FC 5/15 write, FC 1)      discrete input of the twin (FC 2)
//   numeric input      holding register (FC 6/16, 3)   input register of the twin (FC 4)
//   BOOL output        discrete input (FC 2)           coil of the twin (FC 15)
//   numeric output     input register (FC 4)           holding register of the twin (FC 16)
//
// A BOOL takes one bit. A numeric variable takes 1 register (SINT, INT, USINT,
// UINT), 2 (DINT, UDINT, REAL) or 4 (LINT, ULINT, LREAL), most significant
// word first (big-endian, as the Modbus specification orders bytes); REAL
// and LREAL are IEEE 754. Internal variables are never mapped.

#include "core/condition/conditionevaluator.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core::modbusio {

enum class ModbusTable { Coil, DiscreteInput, HoldingRegister, InputRegister };
// "coil", "discrete-input", "holding-register", "input-register"
std::string_view modbusTableName(ModbusTable table);
// The names above, case-insensitive; nullopt otherwise.
std::optional<ModbusTable> parseModbusTable(std::string_view name);
bool isBitTable(ModbusTable table); // coils and discrete inputs

enum class ModbusRole { Server, Client };

inline constexpr int kMaxModbusAddress = 65535;

// The table a variable takes in the role; nullopt for an internal variable.
std::optional<ModbusTable> modbusTableFor(VariableKind kind, IecType type, ModbusRole role);
// Bits (1) or registers (1, 2 or 4) the type takes.
int modbusWidth(IecType type);

struct ModbusEntry {
    std::string variable; // as declared in the model
    IecType type = IecType::Bool;
    VariableKind kind = VariableKind::Input;
    ModbusTable table = ModbusTable::Coil;
    int address = 0; // the first bit or register, 0-based as on the wire
    int width = 1;   // bits or registers
};

// A mapping: its entries in the model's declaration order.
struct ModbusMap {
    ModbusRole role = ModbusRole::Server;
    std::vector<ModbusEntry> entries;

    const ModbusEntry* find(std::string_view variable) const; // case-insensitive
    // The entries of one table, in address order.
    std::vector<const ModbusEntry*> table(ModbusTable table) const;
};

// Every input and output of the model, each table numbered from 0 in the
// variables' declaration order.
ModbusMap defaultModbusMap(const std::vector<Variable>& variables, ModbusRole role);

struct ModbusMapError {
    int line = 0;   // 1-based
    int column = 0; // 1-based, the first character of the field at fault
    std::string message;
    std::string toString(std::string_view path) const; // "PATH:LINE:COLUMN: message"
};

struct ModbusMapParse {
    ModbusMap map;
    std::vector<ModbusMapError> errors; // empty when the map is usable
    bool ok() const { return errors.empty(); }
};

// A CSV mapping: `variable,table,address` per line, an optional header line of
// those three words, blank lines and lines starting with # ignored. Strict:
// a field missing or extra, an unknown variable, an internal one, a variable
// given twice, a table that does not fit the variable's kind and type in the
// role, an address that is not a number in 0..65535 (or whose last register
// passes 65535), and two variables sharing a bit or register are errors with
// their line and column. Variables the file does not name are not linked.
ModbusMapParse parseModbusMap(std::string_view text, const std::vector<Variable>& variables, ModbusRole role);

// The mapping as CSV, with the header line; parseModbusMap reads it back.
std::string writeModbusMap(const ModbusMap& map);

// A value as the registers of its type (modbusWidth(type) of them, most
// significant first); a BOOL as one register 0 or 1.
std::vector<std::uint16_t> encodeModbusValue(IecType type, const cond::Value& value);

// Registers (modbusWidth(type) of them) as a value of the type; nullopt and
// `problem` set ("70000 is out of range for UINT (0..65535)") when they do not
// hold one (a NaN for REAL, an unsigned beyond the 64-bit range).
std::optional<cond::Value> decodeModbusValue(IecType type, const std::uint16_t* registers, std::string& problem);

} // namespace core::modbusio
