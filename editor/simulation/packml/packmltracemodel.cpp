#include "editor/simulation/packml/packmltracemodel.h"

#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/simulation/packml/packmlsimulationtext.h"
#include "editor/stdstring.h"

#include <QStringList>

namespace editor {

PackmlTraceModel::PackmlTraceModel(PackmlSimulationSession* session, QObject* parent)
    : QAbstractTableModel(parent)
    , m_session(session)
{
    connect(m_session, &PackmlSimulationSession::stepped, this, &PackmlTraceModel::refresh);
    connect(m_session, &PackmlSimulationSession::wasReset, this, &PackmlTraceModel::refresh);
    connect(m_session, &PackmlSimulationSession::activeChanged, this, &PackmlTraceModel::refresh);
    connect(m_session, &PackmlSimulationSession::historyMoved, this, &PackmlTraceModel::refresh);
}

void PackmlTraceModel::refresh()
{
    beginResetModel();
    endResetModel();
}

int PackmlTraceModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_session->trace().size());
}

int PackmlTraceModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

int PackmlTraceModel::rowOfScan(qint64 scan) const
{
    const auto& trace = m_session->trace();
    if (trace.empty())
        return -1;
    const qint64 row = scan - trace.front().scan;
    return row >= 0 && row < static_cast<qint64>(trace.size()) ? static_cast<int>(row) : -1;
}

QString PackmlTraceModel::firedText(int row) const
{
    const core::packml::PackmlScanRecord& record = m_session->trace()[static_cast<std::size_t>(row)];
    const core::packml::PackmlProgram& program = m_session->liveSimulator()->program();
    QStringList parts;
    if (record.modeChanged())
        //: a unit mode change in one scan: from, to
        parts << tr("mode %1 → %2").arg(packmlModeName(program, record.modeBefore), packmlModeName(program, record.mode));
    if (record.fired)
        parts << packmlTransitionText(*record.fired);
    if (record.resumed)
        parts << tr("Execute resumed");
    return parts.join(QStringLiteral("; "));
}

QString PackmlTraceModel::droppedText(int row) const
{
    const core::packml::PackmlScanRecord& record = m_session->trace()[static_cast<std::size_t>(row)];
    QStringList lines;
    for (const core::packml::DroppedEvent& event : record.dropped)
        lines << packmlDroppedText(event, m_session->liveSimulator()->program());
    return lines.join(QLatin1Char('\n'));
}

QVariant PackmlTraceModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || !m_session->isActive() || index.row() >= rowCount())
        return {};
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    const core::packml::PackmlScanRecord& record = m_session->trace()[static_cast<std::size_t>(index.row())];
    switch (index.column()) {
    case ScanColumn: return QString::number(static_cast<qlonglong>(record.scan));
    case StateColumn: return fromStd(std::string(core::packml::stateName(record.state)));
    case ModeColumn: return packmlModeName(m_session->liveSimulator()->program(), record.mode);
    case FiredColumn: return firedText(index.row());
    case DroppedColumn: return droppedText(index.row());
    default: return {};
    }
}

QVariant PackmlTraceModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case ScanColumn: return tr("Scan");
    case StateColumn: return tr("State");
    case ModeColumn: return tr("Mode");
    case FiredColumn: return tr("Fired");
    case DroppedColumn: return tr("Dropped");
    default: return {};
    }
}

} // namespace editor
