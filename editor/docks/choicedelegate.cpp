#include "editor/docks/choicedelegate.h"

#include <QComboBox>

namespace editor {

ChoiceDelegate::ChoiceDelegate(Choices choices, const QString& editorName, QObject* parent)
    : QStyledItemDelegate(parent)
    , m_choices(std::move(choices))
    , m_editorName(editorName)
{
}

QWidget* ChoiceDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& /*option*/,
                                      const QModelIndex& /*index*/) const
{
    auto* combo = new QComboBox(parent);
    combo->setObjectName(m_editorName);
    combo->setFrame(false);
    for (const Choice& choice : m_choices())
        combo->addItem(choice.text, choice.value);
    // The popup may be wider than a narrow column.
    combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(combo, &QComboBox::activated, this, [this, combo]() {
        auto* self = const_cast<ChoiceDelegate*>(this);
        emit self->commitData(combo);
        emit self->closeEditor(combo);
    });
    return combo;
}

void ChoiceDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const
{
    auto* combo = static_cast<QComboBox*>(editor);
    const int row = combo->findData(index.data(Qt::EditRole).toString(), Qt::UserRole, Qt::MatchFixedString);
    combo->setCurrentIndex(row >= 0 ? row : 0);
}

void ChoiceDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const
{
    auto* combo = static_cast<QComboBox*>(editor);
    model->setData(index, combo->currentData(), Qt::EditRole);
}

} // namespace editor
