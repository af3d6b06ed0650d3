// The Properties dock: the engineer's verification properties added,
// edited, moved and removed, each one undo step (typing merged), what the
// verifier cannot check underlined as it is typed, the table following undo
// and a model reset.

#include "editor/docks/conditionedit.h"
#include "editor/docks/propertiespanel.h"
#include "editor/docks/propertiestablemodel.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"

#include "core/model/model.h"

#include <QAction>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

using namespace editor;

namespace {

core::Model machine()
{
    core::Model model;
    model.addVariable({"A_Plus", core::IecType::Bool, "", "", core::VariableKind::Input});
    model.addVariable({"A_Minus", core::IecType::Bool, "", "", core::VariableKind::Input});
    return model;
}

QString cell(const PropertiesPanel& dock, int row, int column)
{
    return dock.tableModel()->index(row, column).data().toString();
}

void type(ConditionEdit* edit, const QString& text)
{
    edit->setFocus();
    for (const QChar c : text)
        QTest::keyClick(edit, c.toLatin1());
}

} // namespace

class TestPropertiesPanel : public QObject {
    Q_OBJECT

private slots:
    void addTypeUndoRedo();
    void editCommentInTable();
    void moveAndRemove();
    void problemsUnderlined();
    void followsModelReset();
};

void TestPropertiesPanel::addTypeUndoRedo()
{
    Document document(machine());
    PropertiesPanel dock(&document);
    dock.show();
    dock.findChild<QAction*>(QStringLiteral("addPropertyAction"))->trigger();
    QCOMPARE(document.model().properties().size(), std::size_t{1});
    QCOMPARE(dock.currentRow(), 0);
    type(dock.propertyEdit(), QStringLiteral("never A_Plus"));
    QCOMPARE(document.model().properties()[0].text, std::string("never A_Plus"));
    QCOMPARE(cell(dock, 0, PropertiesTableModel::TextColumn), QStringLiteral("never A_Plus"));
    // Adding is one step, the typing one more.
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    QCOMPARE(document.model().properties()[0].text, std::string());
    QCOMPARE(dock.propertyEdit()->text(), QString());
    document.undoStack()->undo();
    QVERIFY(document.model().properties().empty());
    QCOMPARE(dock.tableModel()->rowCount(), 0);
    document.undoStack()->redo();
    document.undoStack()->redo();
    QCOMPARE(document.model().properties()[0].text, std::string("never A_Plus"));
}

void TestPropertiesPanel::editCommentInTable()
{
    core::Model model = machine();
    model.addProperty({"never A_Plus AND A_Minus", ""});
    Document document(model);
    PropertiesPanel dock(&document);
    QVERIFY(dock.tableModel()->setData(dock.tableModel()->index(0, PropertiesTableModel::CommentColumn),
                                       QStringLiteral("both valves at once")));
    QCOMPARE(document.model().properties()[0].comment, std::string("both valves at once"));
    QVERIFY(dock.tableModel()->setData(dock.tableModel()->index(0, PropertiesTableModel::TextColumn),
                                       QStringLiteral("always NOT (A_Plus AND A_Minus)")));
    QCOMPARE(document.model().properties()[0].text, std::string("always NOT (A_Plus AND A_Minus)"));
    document.undoStack()->undo();
    QCOMPARE(document.model().properties()[0].text, std::string("never A_Plus AND A_Minus"));
}

void TestPropertiesPanel::moveAndRemove()
{
    core::Model model = machine();
    model.addProperty({"never A_Plus", ""});
    model.addProperty({"never A_Minus", ""});
    Document document(model);
    PropertiesPanel dock(&document);
    dock.setCurrentRow(0);
    dock.moveCurrent(1);
    QCOMPARE(document.model().properties()[1].text, std::string("never A_Plus"));
    QCOMPARE(dock.currentRow(), 1);
    QVERIFY(!dock.findChild<QAction*>(QStringLiteral("movePropertyDownAction"))->isEnabled());
    dock.removeCurrent();
    QCOMPARE(document.model().properties().size(), std::size_t{1});
    QCOMPARE(cell(dock, 0, PropertiesTableModel::TextColumn), QStringLiteral("never A_Minus"));
    document.undoStack()->undo();
    QCOMPARE(document.model().properties()[1].text, std::string("never A_Plus"));
    document.undoStack()->undo();
    QCOMPARE(document.model().properties()[0].text, std::string("never A_Plus"));
}

void TestPropertiesPanel::problemsUnderlined()
{
    core::Model model = machine();
    model.addProperty({"never A_Plus AND Ghost", ""});
    Document document(model);
    PropertiesPanel dock(&document);
    dock.show();
    dock.setCurrentRow(0);
    const QList<ConditionEdit::Problem> problems = dock.propertyEdit()->problems();
    QCOMPARE(problems.size(), 1);
    QCOMPARE(problems[0].begin, 17);
    QCOMPARE(problems[0].end, 22);
    QVERIFY(problems[0].message.contains(QStringLiteral("Ghost")));
    QVERIFY(!dock.tableModel()->index(0, 0).data(Qt::DecorationRole).isNull());
    QVERIFY(dock.findChild<WrappingLabel*>(QStringLiteral("propertyProblem"))->isVisibleTo(&dock));

    // Declaring the variable clears it, without touching the property.
    document.modelForCommands().addVariable({"Ghost", core::IecType::Bool, "", "", core::VariableKind::Input});
    QVERIFY(dock.propertyEdit()->problems().isEmpty());
    QVERIFY(dock.tableModel()->index(0, 0).data(Qt::DecorationRole).isNull());

    // A syntax error as it is typed.
    dock.propertyEdit()->selectAll();
    type(dock.propertyEdit(), QStringLiteral("sometimes A"));
    QCOMPARE(dock.propertyEdit()->problems().size(), 1);
    QCOMPARE(dock.propertyEdit()->problems()[0].begin, 0);
}

void TestPropertiesPanel::followsModelReset()
{
    Document document(machine());
    PropertiesPanel dock(&document);
    core::Model other = machine();
    other.addProperty({"always TRUE", "trivial"});
    other.addProperty({"never A_Plus", ""});
    document.modelForCommands().assign(other);
    QCOMPARE(dock.tableModel()->rowCount(), 2);
    QCOMPARE(cell(dock, 0, PropertiesTableModel::CommentColumn), QStringLiteral("trivial"));
}

QTEST_MAIN(TestPropertiesPanel)
#include "test_propertiespanel.moc"
