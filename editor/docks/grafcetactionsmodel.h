#pragma once

#include "core/model/grafcet.h"

#include "editor/docks/grafcetactionparts.h"

#include <QAbstractTableModel>
#include <QString>

#include <map>
#include <tuple>

namespace editor {

class Document;

// The actions of one step of a nested GRAFCET as a table: when each acts,
// its qualifier, its variable and its condition or value
// (GrafcetActionParts), in the order they run. Editing a cell pushes one
// SetGrafcetActionCommand for the whole action; choosing a qualifier or a
// timing keeps the other consistent. Rows the checks object to are red,
// with the problem as tooltip. Each cell edits its own part, in any order:
// the parts as the user set them are kept for as long as the action is what
// they made, since a text cannot hold them all (a qualifier chosen before
// the variable has no spelling of its own).
class GrafcetActionsModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { TimingColumn, QualifierColumn, VariableColumn, OperandColumn, ColumnCount };

    explicit GrafcetActionsModel(Document* document, QObject* parent = nullptr);

    // The step whose actions are shown; an empty id shows none.
    void setStep(const QString& stepId, int number);
    const QString& stepId() const { return m_stepId; }
    int stepNumber() const { return m_number; }

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    // The headers were read in another language: views ask again.
    void retranslate();

    // The action of `row` with the cell of `column` set to `value` (its edit role).
    core::GrafcetAction editedAction(int row, int column, const QString& value) const;
    // What the cells of `row` show.
    GrafcetActionParts parts(int row) const;
    // Why an action's text does not parse, in the UI language; empty when it does.
    static QString syntaxProblem(const core::GrafcetAction& action);
    // What the checks say of the action of `row`, one line per problem; empty for none.
    QString problemText(int row) const;

    // The Timing column's texts and edit values ("continuous", "activation", "deactivation").
    static QString timingText(core::ActionTiming timing);
    static QString timingValue(core::ActionTiming timing);
    static bool parseTiming(const QString& value, core::ActionTiming* timing);

signals:
    // The Document refused an edit; the message says why.
    void editRefused(const QString& message);

private:
    const core::GrafcetStep* step() const;
    void refresh();
    GrafcetActionParts editedParts(int row, int column, const QString& value) const;

    // The parts of an action as its cells last set them, by GEMMA step, nested step and row.
    using RowKey = std::tuple<QString, int, int>;
    std::map<RowKey, GrafcetActionParts> m_setParts;

    Document* m_document;
    QString m_stepId;
    int m_number = 0;
    int m_rowCount = 0; // what the views were told
};

} // namespace editor
