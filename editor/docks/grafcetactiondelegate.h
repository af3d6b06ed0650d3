#pragma once

#include <QStringList>
#include <QStyledItemDelegate>

#include <functional>

class QLineEdit;

namespace editor {

class GrafcetActionsModel;

// Edits the Variable and Condition-or-value cells of a step's action table
// with a line edit that checks, as it is typed, the action the cell would
// make: a text that does not parse turns red, with the reason as tooltip and
// in problemTyped(), before anything is committed. The Variable cell
// completes the names `variableNames` gives at each edit.
class GrafcetActionDelegate : public QStyledItemDelegate {
    Q_OBJECT

public:
    GrafcetActionDelegate(GrafcetActionsModel* model, std::function<QStringList()> variableNames,
                          QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;

signals:
    // The action as typed so far: why it does not parse (empty when it does).
    void problemTyped(const QString& problem) const;

private:
    void validate(QLineEdit* editor, const QModelIndex& index) const;

    GrafcetActionsModel* m_model;
    std::function<QStringList()> m_variableNames;
};

} // namespace editor
