#pragma once

// A QModbusTcpServer that answers for exactly the mapped bits and registers
// (docs/modbus.md, "Exceptions"): a request touching an unmapped address gets
// exception 02 (illegal data address), a function code other than 1-6, 15, 16
// and 23 gets 01 (illegal function), a write whose registers hold no value of
// the variable's type (300 for a USINT, a NaN for a REAL) gets 03 (illegal
// data value) and changes nothing.

#include "core/link/modbusmap.h"

#include <QModbusTcpServer>
#include <QString>

#include <vector>

namespace modbus {

QModbusDataUnit::RegisterType registerType(core::modbusio::ModbusTable table);

// A PDU as its bytes: function code (with 0x80 on an exception), then data.
// QModbusPdu's inline functionCode() loads a byte of 0x80 and above, which
// Qt stores sign-extended, as an invalid enum value (UBSan stops on it):
// the link reads codes through Qt's compiled serialisation instead.
QByteArray pduBytes(const QModbusPdu& pdu);

class MappedModbusServer : public QModbusTcpServer {
    Q_OBJECT

public:
    MappedModbusServer(const core::modbusio::ModbusMap& map, QObject* parent = nullptr);

    // The map entry (index in map.entries) at a table's address; -1 when unmapped.
    int entryAt(core::modbusio::ModbusTable table, int address) const;

signals:
    // A client's write refused: what and where.
    void writeRefused(const QString& message);

protected:
    bool readData(QModbusDataUnit* unit) const override;
    bool writeData(const QModbusDataUnit& unit) override;
    QModbusResponse processRequest(const QModbusPdu& request) override;

private:
    bool allMapped(const QModbusDataUnit& unit) const;

    core::modbusio::ModbusMap m_map;
    std::vector<int> m_owners[4]; // by table: entry index per address, -1 unmapped
    QString m_refusal;            // why the last writeData refused, until processRequest reads it
};

} // namespace modbus
