// The PackML Modes panel (PackmlModesDock, PackmlModeForm): the list, adding,
// removing and renaming modes, the state lists kept consistent (spec §3.2),
// the request condition, the initial mode, the selection.

#include "packmldocktestsupport.h"

#include "editor/docks/diagnosticlist.h"
#include "editor/docks/packml/packmlmodesdock.h"
#include "editor/selection.h"

#include "core/templates/packml/packmlmodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTest>
#include <QUndoStack>

using namespace editor;
using namespace packmldocktest;
using core::packml::Command;
using core::packml::Edition;
using core::packml::State;

namespace {

QStringList listTexts(const QListWidget* list)
{
    QStringList texts;
    for (int row = 0; row < list->count(); ++row)
        texts << list->item(row)->text();
    return texts;
}

void selectListRow(QListWidget* list, const QString& text)
{
    const QList<QListWidgetItem*> found = list->findItems(text, Qt::MatchExactly);
    QVERIFY(!found.isEmpty());
    list->setCurrentItem(found.front());
}

} // namespace

class TestPackmlModesDock : public QObject {
    Q_OBJECT

private slots:
    void modesDockListsAndAddsModes();
    void modesDockRemovesButNotProduction();
    void modesDockRenames();
    void modesDockKeepsDisabledListingConsistent();
    void modesDockModeChangeStates();
    void modesDockRequestAndInitialMode();
    void modesDockFollowsSelection();
};

void TestPackmlModesDock::modesDockListsAndAddsModes()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    QCOMPARE(dock.objectName(), QStringLiteral("packmlModesDock"));
    auto* list = child<QListWidget>(dock, "modeList");
    QCOMPARE(listTexts(list), (QStringList{"1 Production", "2 Maintenance", "3 Manual"}));
    QCOMPARE(dock.currentMode(), 1); // the initial mode
    QVERIFY(child<QLineEdit>(dock, "nameEdit")->isReadOnly());

    QCOMPARE(child<QSpinBox>(dock, "newModeNumber")->value(), 4);
    child<QPushButton>(dock, "addModeButton")->click();
    QCOMPARE(listTexts(list), (QStringList{"1 Production", "2 Maintenance", "3 Manual", "4 Mode4"}));
    QCOMPARE(dock.currentMode(), 4);
    QCOMPARE(selection.current(), ElementRef::packmlMode(4));
    QVERIFY(!child<QLineEdit>(dock, "nameEdit")->isReadOnly());
    QCOMPARE(child<QSpinBox>(dock, "newModeNumber")->value(), 5); // the next free one

    // A number chosen.
    child<QSpinBox>(dock, "newModeNumber")->setValue(20);
    child<QPushButton>(dock, "addModeButton")->click();
    QVERIFY(config(document).mode(20));
    QCOMPARE(config(document).mode(20)->name, std::string("Mode20"));
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(list->count(), 3);
    QCOMPARE(dock.currentMode(), 1); // the shown mode went: back to the initial mode
}

void TestPackmlModesDock::modesDockRemovesButNotProduction()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    auto* remove = child<QPushButton>(dock, "removeModeButton");
    QVERIFY(!remove->isEnabled()); // Production
    selectListRow(child<QListWidget>(dock, "modeList"), QStringLiteral("2 Maintenance"));
    QCOMPARE(selection.current(), ElementRef::packmlMode(2));
    QVERIFY(remove->isEnabled());
    remove->click();
    QVERIFY(!config(document).mode(2));
    QCOMPARE(child<QListWidget>(dock, "modeList")->count(), 2);
    document.undoStack()->undo();
    QVERIFY(config(document).mode(2));
}

void TestPackmlModesDock::modesDockRenames()
{
    core::Model model = core::packml::newModel(Edition::Y2015);
    QVERIFY(model.addMode(4, "Mode4"));
    Document document(model);
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    selection.select(ElementRef::packmlMode(4));
    auto* name = child<QLineEdit>(dock, "nameEdit");
    name->setFocus();
    name->selectAll();
    QTest::keyClicks(name, "Cleaning");
    QCOMPARE(config(document).mode(4)->name, std::string("Mode4")); // not before it is committed
    QTest::keyClick(name, Qt::Key_Return);
    QCOMPARE(config(document).mode(4)->name, std::string("Cleaning"));
    QVERIFY(child<QListWidget>(dock, "modeList")->findItems("4 Cleaning", Qt::MatchExactly).size() == 1);

    // A taken name is refused: the field shows the model's name again.
    QSignalSpy failed(&document, &Document::editFailed);
    name->selectAll();
    QTest::keyClicks(name, "manual");
    QTest::keyClick(name, Qt::Key_Return);
    QCOMPARE(failed.count(), 1);
    QCOMPARE(config(document).mode(4)->name, std::string("Cleaning"));
    QCOMPARE(name->text(), QStringLiteral("Cleaning"));
    QCOMPARE(document.undoStack()->count(), 1);
}

void TestPackmlModesDock::modesDockKeepsDisabledListingConsistent()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    selection.select(ElementRef::packmlMode(3));
    QVERIFY(!child<QCheckBox>(dock, "disabled_Stopped")->isEnabled()); // never disabled
    QVERIFY(!child<QCheckBox>(dock, "disabled_Execute")->isEnabled());

    // Disabling Held disables Holding and Unholding (spec §3.2), one undo step.
    child<QCheckBox>(dock, "disabled_Held")->click();
    QVERIFY((config(document).mode(3)->disabled == core::packml::StateSet{State::Holding, State::Held, State::Unholding}));
    QVERIFY(child<QCheckBox>(dock, "disabled_Holding")->isChecked());
    QVERIFY(child<QCheckBox>(dock, "disabled_Unholding")->isChecked());
    QCOMPARE(document.undoStack()->count(), 1);

    // Enabling Holding enables Held with it; Unholding stays disabled.
    child<QCheckBox>(dock, "disabled_Holding")->click();
    QVERIFY((config(document).mode(3)->disabled == core::packml::StateSet{State::Unholding}));
    QVERIFY(!child<QCheckBox>(dock, "disabled_Held")->isChecked());
    QVERIFY(child<QCheckBox>(dock, "disabled_Unholding")->isChecked());

    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(config(document).mode(3)->disabled.empty());
    QVERIFY(!child<QCheckBox>(dock, "disabled_Held")->isChecked());
}

void TestPackmlModesDock::modesDockModeChangeStates()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    selection.select(ElementRef::packmlMode(3));
    QVERIFY(!dock.findChild<QCheckBox*>(QStringLiteral("modeChange_Starting"))); // no acting state (§3.4)
    QCOMPARE(child<QCheckBox>(dock, "modeChange_Complete")->text(), QStringLiteral("Complete")); // 2015
    QVERIFY(child<QCheckBox>(dock, "modeChange_Idle")->isChecked());
    child<QCheckBox>(dock, "modeChange_Execute")->click();
    child<QCheckBox>(dock, "modeChange_Idle")->click();
    QVERIFY((config(document).mode(3)->modeChange == core::packml::StateSet{State::Stopped, State::Execute, State::Aborted}));
    QCOMPARE(document.undoStack()->count(), 2);

    // A state the mode disables is greyed, as a change there has no effect (PM006).
    child<QCheckBox>(dock, "disabled_Suspended")->click();
    QVERIFY(!child<QCheckBox>(dock, "modeChange_Suspended")->isEnabled());
    QVERIFY(child<QCheckBox>(dock, "modeChange_Held")->isEnabled());
}

void TestPackmlModesDock::modesDockRequestAndInitialMode()
{
    Document document(core::packml::newModel(Edition::Y2022));
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    QCOMPARE(child<QCheckBox>(dock, "disabled_Complete")->text(), QStringLiteral("Completed")); // 2022 (§2.1)
    dock.show();
    selection.select(ElementRef::packmlMode(3));
    auto* request = child<ConditionEdit>(dock, "requestEdit");
    request->setFocus();
    QTest::keyClicks(request, "KeyManual");
    QCOMPARE(config(document).mode(3)->request, std::string("KeyManual"));
    QCOMPARE(document.undoStack()->count(), 1);
    QVERIFY(mentions(request->problems(), "KeyManual")); // not declared
    QVERIFY(child<DiagnosticList>(dock, "modeProblems")->count() > 0);
    document.undoStack()->undo();
    QVERIFY(request->problems().isEmpty());

    auto* initial = child<QComboBox>(dock, "initialModeCombo");
    QCOMPARE(initial->currentText(), QStringLiteral("1 Production"));
    const int manual = initial->findText(QStringLiteral("3 Manual"));
    initial->setCurrentIndex(manual);
    emit initial->activated(manual);
    QCOMPARE(config(document).initialMode, 3);
    document.undoStack()->undo();
    QCOMPARE(initial->currentText(), QStringLiteral("1 Production"));
}

void TestPackmlModesDock::modesDockFollowsSelection()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlModesDock dock(&document, &selection);
    selection.select(ElementRef::packmlMode(2), QStringLiteral("disabled"));
    QCOMPARE(dock.currentMode(), 2);
    QCOMPARE(child<QListWidget>(dock, "modeList")->currentItem()->text(), QStringLiteral("2 Maintenance"));
    // Something else selected: the mode stays shown.
    selection.select(ElementRef::packmlCommand(QStringLiteral("Hold")));
    QCOMPARE(dock.currentMode(), 2);
    // A state picked on the chart showing Manual shows Manual; one in no mode changes nothing.
    selection.select(ElementRef::packmlState(QStringLiteral("Idle"), 3));
    QCOMPARE(dock.currentMode(), 3);
    selection.select(ElementRef::packmlState(QStringLiteral("Idle"), 0));
    QCOMPARE(dock.currentMode(), 3);

    Document gemma;
    PackmlModesDock gemmaDock(&gemma, &selection);
    QCOMPARE(gemmaDock.currentMode(), 0);
    QCOMPARE(gemmaDock.findChild<QStackedWidget*>()->currentWidget(),
             static_cast<QWidget*>(child<QLabel>(gemmaDock, "notPackml")));
}

QTEST_MAIN(TestPackmlModesDock)
#include "test_packmlmodesdock.moc"
