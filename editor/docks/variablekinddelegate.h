#pragma once

#include <QStyledItemDelegate>

namespace editor {

// Edits the Kind column of the variables table with a combo box of the
// translated kinds (input, output, internal); choosing one commits at once.
class VariableKindDelegate : public QStyledItemDelegate {
    Q_OBJECT

public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;
};

} // namespace editor
