#pragma once

#include "core/verification/property.h"

#include <QAbstractTableModel>

#include <vector>

namespace editor {

class Document;

// The Document's verification properties as a table (property, comment).
// Editing a cell pushes the matching command. A property the verifier
// cannot check has an error icon, with what is wrong as tooltip.
class PropertiesTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { TextColumn, CommentColumn, ColumnCount };

    explicit PropertiesTableModel(Document* document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // What is wrong with the property of `row` (empty when it can be checked).
    const std::vector<core::PropertyProblem>& problems(int row) const;

    // The rows as last (re)loaded: the list may have changed since.
    int loadedRows() const { return static_cast<int>(m_problems.size()); }
    // Re-reads the list (rows added, removed, moved) or only the problems.
    void reload();
    void recheck();
    // Whether the next verification runs with single faults, where
    // `faulted` and `T/faulted` are words of a property (else GP007).
    void setFaultAtoms(bool faulted);

private:
    std::vector<core::PropertyProblem> problemsOf(const std::string& text) const;

    Document* m_document;
    std::vector<std::vector<core::PropertyProblem>> m_problems;
    core::PropertyAtoms m_atoms; // setFaultAtoms
};

} // namespace editor
