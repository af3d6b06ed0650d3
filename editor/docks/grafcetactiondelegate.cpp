#include "editor/docks/grafcetactiondelegate.h"

#include "editor/chart/chartstyle.h"
#include "editor/docks/grafcetactionsmodel.h"

#include <QCompleter>
#include <QLineEdit>
#include <QPersistentModelIndex>

namespace editor {

GrafcetActionDelegate::GrafcetActionDelegate(GrafcetActionsModel* model, std::function<QStringList()> variableNames,
                                             QObject* parent)
    : QStyledItemDelegate(parent)
    , m_model(model)
    , m_variableNames(std::move(variableNames))
{
}

QWidget* GrafcetActionDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& /*option*/,
                                             const QModelIndex& index) const
{
    auto* edit = new QLineEdit(parent);
    edit->setObjectName(index.column() == GrafcetActionsModel::VariableColumn ? QStringLiteral("actionVariableEdit")
                                                                              : QStringLiteral("actionOperandEdit"));
    edit->setFrame(false);
    if (index.column() == GrafcetActionsModel::VariableColumn) {
        auto* completer = new QCompleter(m_variableNames(), edit);
        completer->setCaseSensitivity(Qt::CaseInsensitive);
        completer->setFilterMode(Qt::MatchStartsWith);
        edit->setCompleter(completer);
    }
    const QPersistentModelIndex cell(index);
    connect(edit, &QLineEdit::textEdited, this, [this, edit, cell] { validate(edit, cell); });
    return edit;
}

void GrafcetActionDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const
{
    auto* edit = static_cast<QLineEdit*>(editor);
    edit->setText(index.data(Qt::EditRole).toString());
    validate(edit, index);
}

void GrafcetActionDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const
{
    auto* edit = static_cast<QLineEdit*>(editor);
    model->setData(index, edit->text(), Qt::EditRole);
}

void GrafcetActionDelegate::validate(QLineEdit* editor, const QModelIndex& index) const
{
    if (!index.isValid())
        return;
    const QString problem
        = GrafcetActionsModel::syntaxProblem(m_model->editedAction(index.row(), index.column(), editor->text()));
    QPalette palette = editor->parentWidget() ? editor->parentWidget()->palette() : editor->palette();
    if (!problem.isEmpty())
        palette.setColor(QPalette::Text, chartstyle::problemColor());
    editor->setPalette(palette);
    editor->setToolTip(problem);
    emit problemTyped(problem);
}

} // namespace editor
