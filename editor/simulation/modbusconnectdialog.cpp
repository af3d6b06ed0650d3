#include "editor/simulation/modbusconnectdialog.h"

#include "core/formats/fileio.h"
#include "core/model/model.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace editor {

namespace modbusconnectdialog {

QString tableLabel(core::modbusio::ModbusTable table)
{
    switch (table) {
    case core::modbusio::ModbusTable::Coil: return ModbusConnectDialog::tr("Coil");
    case core::modbusio::ModbusTable::DiscreteInput: return ModbusConnectDialog::tr("Discrete input");
    case core::modbusio::ModbusTable::HoldingRegister: return ModbusConnectDialog::tr("Holding register");
    case core::modbusio::ModbusTable::InputRegister: return ModbusConnectDialog::tr("Input register");
    }
    return {};
}

} // namespace modbusconnectdialog

ModbusConnectDialog::ModbusConnectDialog(std::vector<core::Variable> variables, QWidget* parent)
    : QDialog(parent),
      m_variables(std::move(variables)),
      m_role(new QComboBox(this)),
      m_host(new QLineEdit(QStringLiteral("127.0.0.1"), this)),
      m_port(new QSpinBox(this)),
      m_unit(new QSpinBox(this)),
      m_table(new QTableWidget(this)),
      m_problem(new QLabel(this))
{
    setWindowTitle(tr("Connect over Modbus TCP"));
    m_role->addItem(tr("Server: the twin connects to the simulator"));
    m_role->addItem(tr("Client: the simulator connects to the twin"));
    m_port->setRange(1, 65535);
    m_port->setValue(1502);
    m_unit->setRange(0, 255);
    m_unit->setValue(1);
    m_table->setColumnCount(4);
    m_table->setHorizontalHeaderLabels({tr("Variable"), tr("Type"), tr("Table"), tr("Address")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_problem->setWordWrap(true);
    m_problem->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problem->hide();

    auto* form = new QFormLayout;
    form->addRow(tr("Mode:"), m_role);
    form->addRow(tr("Host:"), m_host);
    form->addRow(tr("Port:"), m_port);
    form->addRow(tr("Unit id:"), m_unit);

    auto* load = new QPushButton(tr("Load CSV…"), this);
    auto* save = new QPushButton(tr("Save As CSV…"), this);
    auto* reset = new QPushButton(tr("Default Map"), this);
    load->setObjectName(QStringLiteral("loadMapButton"));
    save->setObjectName(QStringLiteral("saveMapButton"));
    auto* mapButtons = new QHBoxLayout;
    mapButtons->addWidget(load);
    mapButtons->addWidget(save);
    mapButtons->addWidget(reset);
    mapButtons->addStretch(1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton* connectButton = buttons->addButton(tr("Connect"), QDialogButtonBox::AcceptRole);
    connectButton->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("Map (each table numbered from 0 in declaration order unless loaded):"), this));
    layout->addWidget(m_table, 1);
    layout->addLayout(mapButtons);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);

    connect(m_role, &QComboBox::currentIndexChanged, this, &ModbusConnectDialog::onRoleChanged);
    connect(reset, &QPushButton::clicked, this, &ModbusConnectDialog::onRoleChanged);
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Modbus Map"), QString(), tr("CSV files (*.csv)"));
        if (!path.isEmpty())
            loadMap(path);
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save Modbus Map"), QStringLiteral("modbus-map.csv"),
                                                          tr("CSV files (*.csv)"));
        if (!path.isEmpty())
            saveMap(path);
    });
    onRoleChanged();
    resize(560, 520);
}

void ModbusConnectDialog::onRoleChanged()
{
    const auto role = m_role->currentIndex() == 1 ? core::modbusio::ModbusRole::Client : core::modbusio::ModbusRole::Server;
    if (m_role->currentIndex() == 1 && m_port->value() == 1502)
        m_port->setValue(502); // a twin usually serves on Modbus's own port
    else if (m_role->currentIndex() == 0 && m_port->value() == 502)
        m_port->setValue(1502);
    m_map = core::modbusio::defaultModbusMap(m_variables, role);
    m_problem->hide();
    fillTable();
}

void ModbusConnectDialog::fillTable()
{
    m_table->setRowCount(static_cast<int>(m_map.entries.size()));
    int row = 0;
    for (const core::modbusio::ModbusEntry& entry : m_map.entries) {
        QString address = QString::number(entry.address);
        if (entry.width > 1)
            address += QStringLiteral("..%1").arg(entry.address + entry.width - 1);
        const QStringList cells{QString::fromStdString(entry.variable),
                                QString::fromUtf8(core::iecTypeName(entry.type).data(),
                                                  static_cast<qsizetype>(core::iecTypeName(entry.type).size())),
                                modbusconnectdialog::tableLabel(entry.table), address};
        for (int column = 0; column < cells.size(); ++column)
            m_table->setItem(row, column, new QTableWidgetItem(cells[column]));
        ++row;
    }
    m_table->resizeColumnsToContents();
}

bool ModbusConnectDialog::loadMap(const QString& path)
{
    std::string text;
    const core::Status status = core::readFileLimited(path.toStdString(), 4u * 1024u * 1024u, text);
    QStringList problems;
    core::modbusio::ModbusMapParse parsed;
    if (!status) {
        problems << QString::fromStdString(status.message);
    } else {
        parsed = core::modbusio::parseModbusMap(text, m_variables, m_map.role);
        for (const core::modbusio::ModbusMapError& error : parsed.errors)
            problems << tr("Line %1, column %2: %3").arg(error.line).arg(error.column).arg(QString::fromStdString(error.message));
    }
    if (!problems.isEmpty()) {
        m_problem->setText(tr("%1 cannot be used:").arg(path) + QLatin1Char('\n') + problems.join(QLatin1Char('\n')));
        m_problem->show();
        return false;
    }
    m_map = parsed.map;
    m_problem->hide();
    fillTable();
    return true;
}

bool ModbusConnectDialog::saveMap(const QString& path)
{
    const core::Status status = core::writeFileAtomically(path.toStdString(), core::modbusio::writeModbusMap(m_map));
    if (!status) {
        m_problem->setText(tr("%1 could not be saved: %2").arg(path, QString::fromStdString(status.message)));
        m_problem->show();
        return false;
    }
    m_problem->hide();
    return true;
}

modbus::ModbusLinkOptions ModbusConnectDialog::options() const
{
    modbus::ModbusLinkOptions options;
    options.map = m_map;
    options.host = m_host->text().trimmed();
    options.port = m_port->value();
    options.unitId = m_unit->value();
    return options;
}

} // namespace editor
