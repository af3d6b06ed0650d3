#pragma once

#include "core/checks/diagnostic.h"
#include "core/model/model.h"

#include <QAbstractTableModel>

#include <optional>
#include <vector>

class QUndoCommand;

namespace editor {

class Document;

// The Document's variables as a table (name, type, kind, default, comment).
// Editing a cell pushes the matching command: renaming rewrites every
// condition that uses the variable. Cells the checks object to are red,
// with the problem as tooltip. A refused edit (a duplicate name) leaves the
// cell as it was and is reported by editRefused().
class VariablesTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { NameColumn, TypeColumn, KindColumn, DefaultColumn, CommentColumn, ColumnCount };

    explicit VariablesTableModel(Document* document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    // The headers and tooltips were read in another language: views ask again.
    void retranslate();

    QString variableName(int row) const;
    int rowOf(const QString& name) const; // case-insensitive; -1 when absent

    // "Input", "Output", "Internal" in the UI language: what the Kind column shows.
    static QString kindText(core::VariableKind kind);
    // A kind by its file name ("output") or its kindText(), ignoring case.
    static std::optional<core::VariableKind> parseKind(const QString& text);

    // The column of a diagnostic field ("name", "default"...); -1 for none.
    static int columnOfField(const QString& field);

    // Rows copied from a spreadsheet, one variable a line:
    // name[TAB]type[TAB]default[TAB]comment[TAB]kind. A first line whose
    // first cell says "Name" is a header; blank lines are skipped; a missing
    // type is BOOL, a missing kind input. A fifth cell that names no kind
    // is ignored unless the header calls that column "Kind". False with a message naming the line on bad input.
    static bool parseRows(const QString& text, std::vector<core::Variable>* variables, QString* error);
    // The same format, header line included, for the clipboard.
    static QString formatRows(const std::vector<core::Variable>& variables);

signals:
    // The Document refused an edit of this cell; the message says why.
    void editRefused(const QModelIndex& index, const QString& message);
    void variableRenamed(const QString& oldName, const QString& newName);

private:
    const core::Variable* variableAt(int row) const;
    QVariant displayData(const core::Variable& variable, int column) const;
    QVariant toolTip(const core::Variable& variable, int column) const;
    std::vector<core::Diagnostic> diagnostics(const core::Variable& variable, int column) const;
    bool pushEdit(const QModelIndex& index, QUndoCommand* command);
    void onVariablesChanged();
    void onVariableChanged(const QString& name);
    void onDiagnosticsChanged();

    Document* m_document;
    int m_rowCount = 0; // what the views were told
};

} // namespace editor
