#include "editor/modbus/mappedmodbusserver.h"

#include <QDataStream>
#include <QModbusDataUnitMap>
#include <QModbusTcpConnectionObserver>

#include <algorithm>

namespace modbus {

using core::modbusio::ModbusTable;

QModbusDataUnit::RegisterType registerType(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coil: return QModbusDataUnit::Coils;
    case ModbusTable::DiscreteInput: return QModbusDataUnit::DiscreteInputs;
    case ModbusTable::HoldingRegister: return QModbusDataUnit::HoldingRegisters;
    case ModbusTable::InputRegister: return QModbusDataUnit::InputRegisters;
    }
    return QModbusDataUnit::Invalid;
}

QByteArray pduBytes(const QModbusPdu& pdu)
{
    QByteArray bytes;
    QDataStream stream(&bytes, QIODevice::WriteOnly);
    stream << pdu;
    return bytes;
}

namespace mappedmodbusserver {

int tableIndex(QModbusDataUnit::RegisterType type)
{
    switch (type) {
    case QModbusDataUnit::Coils: return static_cast<int>(ModbusTable::Coil);
    case QModbusDataUnit::DiscreteInputs: return static_cast<int>(ModbusTable::DiscreteInput);
    case QModbusDataUnit::HoldingRegisters: return static_cast<int>(ModbusTable::HoldingRegister);
    case QModbusDataUnit::InputRegisters: return static_cast<int>(ModbusTable::InputRegister);
    default: return -1;
    }
}

} // namespace mappedmodbusserver

MappedModbusServer::MappedModbusServer(const core::modbusio::ModbusMap& map, QObject* parent)
    : QModbusTcpServer(parent), m_map(map)
{
    QModbusDataUnitMap units;
    for (int t = 0; t < 4; ++t) {
        const auto table = static_cast<ModbusTable>(t);
        int end = 0;
        int first = core::modbusio::kMaxModbusAddress + 1;
        for (const core::modbusio::ModbusEntry& entry : m_map.entries) {
            if (entry.table == table) {
                end = std::max(end, entry.address + entry.width);
                first = std::min(first, entry.address);
            }
        }
        m_owners[t].assign(static_cast<std::size_t>(end), -1);
        for (std::size_t i = 0; i < m_map.entries.size(); ++i) {
            const core::modbusio::ModbusEntry& entry = m_map.entries[i];
            if (entry.table != table)
                continue;
            for (int a = entry.address; a < entry.address + entry.width; ++a)
                m_owners[t][static_cast<std::size_t>(a)] = static_cast<int>(i);
        }
        if (end > 0) // the span from the first to the last mapped address; readData refuses its gaps
            units.insert(registerType(table),
                         QModbusDataUnit(registerType(table), first, static_cast<quint16>(end - first)));
    }
    setMap(units);
}

int MappedModbusServer::entryAt(ModbusTable table, int address) const
{
    const std::vector<int>& owners = m_owners[static_cast<int>(table)];
    if (address < 0 || static_cast<std::size_t>(address) >= owners.size())
        return -1;
    return owners[static_cast<std::size_t>(address)];
}

bool MappedModbusServer::allMapped(const QModbusDataUnit& unit) const
{
    const int t = mappedmodbusserver::tableIndex(unit.registerType());
    if (t < 0 || unit.valueCount() == 0)
        return false;
    for (qsizetype i = 0; i < unit.valueCount(); ++i) {
        if (entryAt(static_cast<ModbusTable>(t), unit.startAddress() + static_cast<int>(i)) < 0)
            return false;
    }
    return true;
}

bool MappedModbusServer::readData(QModbusDataUnit* unit) const
{
    return unit && allMapped(*unit) && QModbusTcpServer::readData(unit);
}

bool MappedModbusServer::writeData(const QModbusDataUnit& unit)
{
    if (!allMapped(unit))
        return false;
    const int t = mappedmodbusserver::tableIndex(unit.registerType());
    const auto table = static_cast<ModbusTable>(t);
    if (core::modbusio::isBitTable(table)) // a coil is TRUE when non-zero (FC 5 sends 0xFF00)
        return QModbusTcpServer::writeData(unit);
    // Each variable the write touches must still hold a value of its type.
    int lastEntry = -1;
    for (qsizetype i = 0; i < unit.valueCount(); ++i) {
        const int address = unit.startAddress() + static_cast<int>(i);
        const int index = entryAt(table, address);
        if (index == lastEntry)
            continue;
        lastEntry = index;
        const core::modbusio::ModbusEntry& entry = m_map.entries[static_cast<std::size_t>(index)];
        std::vector<std::uint16_t> registers(static_cast<std::size_t>(entry.width));
        for (int w = 0; w < entry.width; ++w) {
            const int at = entry.address + w;
            quint16 value = 0;
            if (at >= unit.startAddress() && at < unit.startAddress() + unit.valueCount())
                value = unit.value(at - unit.startAddress());
            else
                QModbusTcpServer::data(unit.registerType(), static_cast<quint16>(at), &value);
            registers[static_cast<std::size_t>(w)] = value;
        }
        std::string problem;
        if (!core::modbusio::decodeModbusValue(entry.type, registers.data(), problem)) {
            m_refusal = QStringLiteral("%1 %2 (%3): %4")
                            .arg(QString::fromStdString(std::string(core::modbusio::modbusTableName(table))))
                            .arg(entry.address)
                            .arg(QString::fromStdString(entry.variable), QString::fromStdString(problem));
            return false;
        }
    }
    return QModbusTcpServer::writeData(unit);
}

QModbusResponse MappedModbusServer::processRequest(const QModbusPdu& request)
{
    const QByteArray bytes = pduBytes(request);
    const auto code = static_cast<QModbusPdu::FunctionCode>(bytes.isEmpty() ? 0 : static_cast<quint8>(bytes.at(0)) & 0x7F);
    switch (bytes.isEmpty() ? 0 : static_cast<quint8>(bytes.at(0))) {
    case QModbusPdu::ReadCoils:
    case QModbusPdu::ReadDiscreteInputs:
    case QModbusPdu::ReadHoldingRegisters:
    case QModbusPdu::ReadInputRegisters:
    case QModbusPdu::WriteSingleCoil:
    case QModbusPdu::WriteSingleRegister:
    case QModbusPdu::WriteMultipleCoils:
    case QModbusPdu::WriteMultipleRegisters:
    case QModbusPdu::ReadWriteMultipleRegisters: break;
    default: return QModbusExceptionResponse(code, QModbusExceptionResponse::IllegalFunction);
    }
    m_refusal.clear();
    QModbusResponse response = QModbusTcpServer::processRequest(request);
    if (!m_refusal.isEmpty()) {
        const QString refusal = m_refusal;
        m_refusal.clear();
        emit writeRefused(refusal);
        return QModbusExceptionResponse(code, QModbusExceptionResponse::IllegalDataValue);
    }
    return response;
}

} // namespace modbus
