#pragma once

#include <QAbstractTableModel>

namespace editor {

class PackmlSimulationSession;

// The scans of a PackML simulation as a table, one row per scan kept in the
// session's trace: its number, the state and mode after it, the transition
// that fired (with the mode change and a resumed Execute), and every event
// it dropped with its reason worded. Rebuilt after each batch of scans.
class PackmlTraceModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { ScanColumn, StateColumn, ModeColumn, FiredColumn, DroppedColumn, ColumnCount };

    explicit PackmlTraceModel(PackmlSimulationSession* session, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The row of a scan, -1 when the trace no longer keeps it.
    int rowOfScan(qint64 scan) const;

public slots:
    void refresh();

private:
    QString firedText(int row) const;
    QString droppedText(int row) const;

    PackmlSimulationSession* m_session;
};

} // namespace editor
