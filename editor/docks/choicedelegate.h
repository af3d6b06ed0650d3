#pragma once

#include <QList>
#include <QString>
#include <QStyledItemDelegate>

#include <functional>

namespace editor {

// Edits a table column with a combo box of fixed choices (the Variables
// table's Type and Kind); choosing one commits at once. Each choice is the
// text shown and the value the column's edit role takes; the choices are
// asked for at each edit, so that translated texts follow the language.
class ChoiceDelegate : public QStyledItemDelegate {
    Q_OBJECT

public:
    struct Choice {
        QString text;
        QString value;
    };
    using Choices = std::function<QList<Choice>()>;

    // `editorName` names the combo box (for tests and accessibility).
    ChoiceDelegate(Choices choices, const QString& editorName, QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;

private:
    Choices m_choices;
    QString m_editorName;
};

} // namespace editor
