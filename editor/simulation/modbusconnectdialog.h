#pragma once

// Simulation > Connect…: server or client, host, port and unit id, and the
// Modbus map (docs/modbus.md): the default one, or one loaded from a CSV file,
// shown as a table and saved as CSV. Connect hands the options to the caller.

#include "core/link/modbusmap.h"
#include "editor/modbus/modbuslink.h"

#include <QDialog>

#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;

namespace core {
struct Variable;
}

namespace editor {

class ModbusConnectDialog : public QDialog {
    Q_OBJECT

public:
    ModbusConnectDialog(std::vector<core::Variable> variables, QWidget* parent = nullptr);

    modbus::ModbusLinkOptions options() const;

    QComboBox* roleCombo() const { return m_role; }
    QLineEdit* hostEdit() const { return m_host; }
    QSpinBox* portSpin() const { return m_port; }
    QSpinBox* unitSpin() const { return m_unit; }
    QTableWidget* mapTable() const { return m_table; }
    QLabel* problemLabel() const { return m_problem; }

    // Reads a CSV map for the chosen role; false with its problems shown (the
    // map in use stays) when it does not fit the model.
    bool loadMap(const QString& path);
    // Writes the map in use as CSV; false with the reason shown.
    bool saveMap(const QString& path);

private:
    void onRoleChanged();
    void fillTable();

    std::vector<core::Variable> m_variables;
    core::modbusio::ModbusMap m_map;
    QComboBox* m_role;
    QLineEdit* m_host;
    QSpinBox* m_port;
    QSpinBox* m_unit;
    QTableWidget* m_table;
    QLabel* m_problem;
};

} // namespace editor
