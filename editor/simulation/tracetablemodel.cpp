#include "editor/simulation/tracetablemodel.h"

#include "editor/simulation/simulationsession.h"
#include "editor/text/elementlabels.h"

#include "core/condition/conditionevaluator.h"

#include <QStringList>

namespace editor {

namespace {

QString boolText(bool value)
{
    return value ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
}

QString tokensText(const core::Simulator& simulator, const std::vector<bool>& tokens)
{
    QStringList set;
    const std::vector<std::string>& names = simulator.tokenNames();
    for (std::size_t i = 0; i < tokens.size() && i < names.size(); ++i) {
        if (tokens[i])
            set << QString::fromStdString(names[i]);
    }
    return set.join(QStringLiteral(", "));
}

QString inputsText(const std::vector<core::InputChange>& changes)
{
    QStringList texts;
    for (const core::InputChange& change : changes)
        texts << QStringLiteral("%1 = %2").arg(QString::fromStdString(change.variable),
                                               QString::fromStdString(core::cond::formatValue(change.value)));
    return texts.join(QStringLiteral(", "));
}

} // namespace

TraceTableModel::TraceTableModel(SimulationSession* session, QObject* parent)
    : QAbstractTableModel(parent)
    , m_session(session)
{
    sync();
}

int TraceTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

int TraceTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TraceTableModel::data(const QModelIndex& index, int role) const
{
    const core::Simulator* simulator = m_session->simulator();
    if (!simulator || !index.isValid() || index.row() >= m_rows
        || static_cast<std::size_t>(index.row()) >= m_session->trace().size())
        return {};
    const core::ScanRecord& record = m_session->trace()[static_cast<std::size_t>(index.row())];
    if (role == Qt::TextAlignmentRole && index.column() == ScanColumn)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    switch (index.column()) {
    case ScanColumn: return QString::number(record.scan);
    case StepColumn: return QString::fromStdString(record.stepAfter);
    case FiredColumn: return record.fired.empty() ? QString() : transitionLabel(QString::fromStdString(record.fired));
    case EntryColumn: return boolText(record.entry);
    case TokensColumn: return tokensText(*simulator, record.tokens);
    case InputsColumn: return inputsText(record.changedInputs);
    default: return {};
    }
}

void TraceTableModel::retranslate()
{
    emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
}

QVariant TraceTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case ScanColumn: return tr("Scan");
    case StepColumn: return tr("Step");
    case FiredColumn: return tr("Fired");
    case EntryColumn: return tr("Entry");
    case TokensColumn: return tr("Tokens TRUE");
    case InputsColumn: return tr("Changed inputs");
    default: return {};
    }
}

void TraceTableModel::reload()
{
    beginResetModel();
    m_rows = 0;
    m_firstScan = 0;
    endResetModel();
    sync();
}

void TraceTableModel::sync()
{
    const std::deque<core::ScanRecord>& trace = m_session->trace();
    const int rows = static_cast<int>(trace.size());
    const std::int64_t firstScan = trace.empty() ? 0 : trace.front().scan;
    if (rows == m_rows && firstScan == m_firstScan)
        return;
    // Scans only come at the end and go from the front, except after a reset.
    const std::int64_t dropped = firstScan - m_firstScan;
    const bool incremental = m_rows > 0 && rows > 0 && dropped >= 0 && dropped <= m_rows
                          && trace.back().scan >= m_firstScan + m_rows - 1;
    if (!incremental) {
        beginResetModel();
        m_rows = rows;
        m_firstScan = firstScan;
        endResetModel();
        return;
    }
    if (dropped > 0) {
        beginRemoveRows({}, 0, static_cast<int>(dropped) - 1);
        m_rows -= static_cast<int>(dropped);
        m_firstScan = firstScan;
        endRemoveRows();
    }
    if (rows > m_rows) {
        beginInsertRows({}, m_rows, rows - 1);
        m_rows = rows;
        endInsertRows();
    }
}

} // namespace editor
