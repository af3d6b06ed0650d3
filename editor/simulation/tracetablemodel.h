#pragma once

#include <QAbstractTableModel>

#include <cstdint>

namespace editor {

class SimulationSession;

// The session's trace as a table, one row per scan (the latest
// SimulationSession::kTraceCapacity). sync() turns the scans added and
// dropped since the last call into row insertions and removals, so a view
// at the bottom keeps following without a full reset every frame.
class TraceTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { ScanColumn, StepColumn, FiredColumn, EntryColumn, TokensColumn, InputsColumn, ColumnCount };

    explicit TraceTableModel(SimulationSession* session, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    // The headers were read in another language: views ask again.
    void retranslate();

    void sync();
    // After a reset, when the rows of the same scan numbers hold other scans.
    void reload();

private:
    SimulationSession* m_session;
    int m_rows = 0;
    std::int64_t m_firstScan = 0; // of row 0 when m_rows > 0
};

} // namespace editor
