// The PackML State panel (PackmlStateDock): what the selected state is, its
// nested GRAFCET per mode (own, same as, none), Open GRAFCET, its problems.

#include "packmldocktestsupport.h"

#include "editor/commands/packml/setgrafcetchoicecommand.h"
#include "editor/commands/packml/setmodestatescommand.h"
#include "editor/docks/diagnosticlist.h"
#include "editor/docks/packml/packmlstatedock.h"
#include "editor/selection.h"
#include "editor/text/packmltexts.h"

#include "core/templates/packml/packmlmodel.h"

#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QTest>
#include <QUndoStack>

using namespace editor;
using namespace packmldocktest;
using core::packml::Command;
using core::packml::Edition;
using core::packml::State;

class TestPackmlStateDock : public QObject {
    Q_OBJECT

private slots:
    void stateDockShowsTheSelectedState();
    void stateDockGrafcetChoices();
    void stateDockWaitStateAndGemma();
};

void TestPackmlStateDock::stateDockShowsTheSelectedState()
{
    Document document(core::packml::newModel(Edition::Y2022));
    Selection selection;
    PackmlStateDock dock(&document, &selection);
    QCOMPARE(dock.objectName(), QStringLiteral("packmlStateDock"));
    auto* pages = dock.findChild<QStackedWidget*>();
    QCOMPARE(pages->currentWidget(), static_cast<QWidget*>(child<QLabel>(dock, "placeholder")));

    selection.select(ElementRef::packmlState(QStringLiteral("Complete"), 1));
    QCOMPARE(dock.stateName(), QStringLiteral("Complete"));
    QCOMPARE(child<QLabel>(dock, "stateTitle")->text(), QStringLiteral("17 Completed")); // 2022 (§2.1)
    QCOMPARE(child<QLabel>(dock, "stateMeaning")->text(), packmltext::stateMeaning(State::Complete));

    selection.select(ElementRef::packmlState(QStringLiteral("Execute"), 3));
    QCOMPARE(child<QLabel>(dock, "stateTitle")->text(), QStringLiteral("6 Execute"));
    QCOMPARE(child<QLabel>(dock, "stateKind")->text(), packmltext::stateKindName(core::packml::StateKind::Dual));
    // One choice per mode, the mode it was selected in first.
    auto* grid = child<QGroupBox>(dock, "grafcetGroup");
    QList<QComboBox*> combos = grid->findChildren<QComboBox*>();
    QCOMPARE(combos.size(), 3);
    QVERIFY(child<QComboBox>(dock, "choice_3"));
    QCOMPARE(child<QComboBox>(dock, "choice_3")->currentText(), QStringLiteral("None (skeleton)"));
}

void TestPackmlStateDock::stateDockGrafcetChoices()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlStateDock dock(&document, &selection);
    QSignalSpy open(&dock, &PackmlStateDock::openGrafcetRequested);
    selection.select(ElementRef::packmlState(QStringLiteral("Starting"), 1));
    QVERIFY(!child<QPushButton>(dock, "open_1")->isEnabled()); // none: nothing to open

    // Own creates the GRAFCET, as the core expects.
    auto* choice = child<QComboBox>(dock, "choice_1");
    const int own = choice->findText(QStringLiteral("Own GRAFCET"));
    choice->setCurrentIndex(own);
    emit choice->activated(own);
    QVERIFY(document.model().grafcet("1/Starting"));
    QCOMPARE(config(document).mode(1)->grafcetChoice(State::Starting), core::packml::GrafcetChoice::own());
    child<QPushButton>(dock, "open_1")->click();
    QCOMPARE(open.count(), 1);
    QCOMPARE(open.last().at(0).toString(), QStringLiteral("1/Starting"));

    // Manual offers "same as" Production now that Production has its own; it opens Production's.
    auto* manual = child<QComboBox>(dock, "choice_3");
    const int same = manual->findText(QStringLiteral("Same as 1 Production"));
    QVERIFY(same >= 0);
    QCOMPARE(child<QComboBox>(dock, "choice_2")->findText(QStringLiteral("Same as 3 Manual")), -1); // no chains
    manual->setCurrentIndex(same);
    emit manual->activated(same);
    QCOMPARE(config(document).mode(3)->grafcetChoice(State::Starting), core::packml::GrafcetChoice::sameAs(1));
    child<QPushButton>(dock, "open_3")->click();
    QCOMPARE(open.last().at(0).toString(), QStringLiteral("1/Starting"));
    QCOMPARE(document.undoStack()->count(), 2);

    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(!document.model().grafcet("1/Starting"));
    QCOMPARE(child<QComboBox>(dock, "choice_1")->currentText(), QStringLiteral("None (skeleton)"));
}

void TestPackmlStateDock::stateDockWaitStateAndGemma()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Selection selection;
    PackmlStateDock dock(&document, &selection);
    selection.select(ElementRef::packmlState(QStringLiteral("Idle"), 1));
    QCOMPARE(child<QLabel>(dock, "stateTitle")->text(), QStringLiteral("4 Idle"));
    QVERIFY(child<QGroupBox>(dock, "grafcetGroup")->findChildren<QComboBox*>().isEmpty());
    QVERIFY(!child<QLabel>(dock, "grafcetHint")->text().isEmpty());

    // The state's problems: a GRAFCET of its own in a mode that disables it (PM014).
    QVERIFY(document.push(new SetGrafcetChoiceCommand(document, 3, State::Clearing, core::packml::GrafcetChoice::own())));
    QVERIFY(document.push(new SetModeStatesCommand(document, 3, SetModeStatesCommand::List::Disabled,
                                                   core::packml::StateSet{State::Clearing})));
    selection.select(ElementRef::packmlState(QStringLiteral("Clearing"), 3));
    QVERIFY(child<DiagnosticList>(dock, "stateProblems")->count() > 0);

    document.replaceModel(core::Model(), QString(), core::ModelFormat::Native);
    QCOMPARE(dock.findChild<QStackedWidget*>()->currentWidget(),
             static_cast<QWidget*>(child<QLabel>(dock, "placeholder")));
}

QTEST_MAIN(TestPackmlStateDock)
#include "test_packmlstatedock.moc"
