#include "editor/docks/variablekinddelegate.h"

#include "editor/docks/variablestablemodel.h"

#include "core/model/model.h"

#include <QComboBox>

namespace editor {

QWidget* VariableKindDelegate::createEditor(
    QWidget* parent, const QStyleOptionViewItem& /*option*/, const QModelIndex& /*index*/) const
{
    auto* combo = new QComboBox(parent);
    combo->setObjectName(QStringLiteral("kindCombo"));
    combo->setFrame(false);
    // The item data is the kind's file name, the column's edit role.
    for (core::VariableKind kind :
        { core::VariableKind::Input, core::VariableKind::Output, core::VariableKind::Internal }) {
        const std::string_view name = core::variableKindName(kind);
        combo->addItem(
            VariablesTableModel::kindText(kind), QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())));
    }
    // The popup may be wider than the narrow column.
    combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(combo, &QComboBox::activated, this, [this, combo]() {
        auto* self = const_cast<VariableKindDelegate*>(this);
        emit self->commitData(combo);
        emit self->closeEditor(combo);
    });
    return combo;
}

void VariableKindDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const
{
    auto* combo = static_cast<QComboBox*>(editor);
    const int row = combo->findData(index.data(Qt::EditRole).toString());
    combo->setCurrentIndex(row >= 0 ? row : 0);
}

void VariableKindDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const
{
    auto* combo = static_cast<QComboBox*>(editor);
    model->setData(index, combo->currentData(), Qt::EditRole);
}

} // namespace editor
