#include "editor/docks/variabletypedelegate.h"

#include "core/model/iectypes.h"

#include <QComboBox>

namespace editor {

QWidget* VariableTypeDelegate::createEditor(
    QWidget* parent, const QStyleOptionViewItem& /*option*/, const QModelIndex& /*index*/) const
{
    auto* combo = new QComboBox(parent);
    combo->setFrame(false);
    for (core::IecType type : core::allIecTypes()) {
        const std::string_view name = core::iecTypeName(type);
        combo->addItem(QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())));
    }
    connect(combo, &QComboBox::activated, this, [this, combo]() {
        auto* self = const_cast<VariableTypeDelegate*>(this);
        emit self->commitData(combo);
        emit self->closeEditor(combo);
    });
    return combo;
}

void VariableTypeDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const
{
    auto* combo = static_cast<QComboBox*>(editor);
    const int row = combo->findText(index.data(Qt::EditRole).toString(), Qt::MatchFixedString);
    combo->setCurrentIndex(row >= 0 ? row : 0);
}

void VariableTypeDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const
{
    auto* combo = static_cast<QComboBox*>(editor);
    model->setData(index, combo->currentText(), Qt::EditRole);
}

} // namespace editor
