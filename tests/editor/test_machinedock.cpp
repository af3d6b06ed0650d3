// The Machine dock and the machine's undo commands (issue 35): adding,
// removing and wiring components, each change one undoable command, the
// variables offered filtered by what the role needs, and the machine's
// checks (GG601-GG608) in the Problems dock.

#include "editortestsupport.h"

#include "editor/app/languages.h"
#include "editor/docks/machinedock.h"
#include "editor/docks/problemsdock.h"
#include "editor/document.h"
#include "editor/machine/machinetab.h"
#include "editor/mainwindow.h"

#include "core/formats/modelfiles.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>

#include <memory>

using namespace editor;

class TestMachineDock : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void addAndRemoveAreUndoable();
    void roleDropDownsOfferTheVariablesThatFit();
    void wiringIsOneUndoableCommand();
    void timeStepsMergeIntoOneCommand();
    void renamingAConveyorKeepsItsSources();
    void lockedWhileSimulating();
    void firstComponentBringsTheMachineTab();
    void machineChecksAreInTheProblemsDock();

private:
    const core::machine::Machine& machine() const { return m_document->model().machine(); }
    void chooseInCombo(QComboBox* combo, const QString& text);

    std::unique_ptr<Document> m_document;
    std::unique_ptr<MachineDock> m_dock;
    QTemporaryDir m_settingsDir;
};

void TestMachineDock::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    editortest::useTestSettings(m_settingsDir.path(), QStringLiteral("test_machinedock"));
}

void TestMachineDock::init()
{
    const core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json");
    QVERIFY(loaded.model);
    m_document = std::make_unique<Document>(*loaded.model);
    m_dock = std::make_unique<MachineDock>(m_document.get());
    m_dock->show();
}

void TestMachineDock::cleanup()
{
    m_dock.reset();
    m_document.reset();
}

// As the user picks an entry: activated() follows.
void TestMachineDock::chooseInCombo(QComboBox* combo, const QString& text)
{
    QVERIFY(combo);
    const int index = combo->findText(text);
    QVERIFY2(index >= 0, qPrintable(text));
    combo->setCurrentIndex(index);
    emit combo->activated(index);
}

void TestMachineDock::addAndRemoveAreUndoable()
{
    QCOMPARE(m_dock->componentList()->count(), 9);
    QCOMPARE(m_dock->currentComponent(), 0); // the first one's form shows at once
    QCOMPARE(m_dock->nameEdit()->text(), QStringLiteral("Clamp"));
    m_dock->kindCombo()->setCurrentIndex(m_dock->kindCombo()->findText(QStringLiteral("Conveyor")));
    QTest::mouseClick(m_dock->addButton(), Qt::LeftButton);
    QCOMPARE(machine().components.size(), std::size_t{10});
    QCOMPARE(machine().components.back().kind, core::machine::ComponentKind::Conveyor);
    QCOMPARE(machine().components.back().name, std::string("Conveyor")); // unique: the example has "Infeed"
    QCOMPARE(m_dock->componentList()->count(), 10);
    QCOMPARE(m_dock->currentComponent(), 9);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Add Conveyor Conveyor"));
    QTest::mouseClick(m_dock->addButton(), Qt::LeftButton);
    QCOMPARE(machine().components.back().name, std::string("Conveyor2"));

    const core::machine::Machine before = machine();
    m_dock->selectComponent(0);
    QTest::mouseClick(m_dock->removeButton(), Qt::LeftButton);
    QVERIFY(!machine().find("Clamp"));
    QCOMPARE(m_dock->componentList()->count(), 10);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Remove Clamp"));
    m_document->undoStack()->undo();
    QVERIFY(machine() == before);
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QCOMPARE(machine().components.size(), std::size_t{9});
    QCOMPARE(m_dock->componentList()->count(), 9);
}

void TestMachineDock::roleDropDownsOfferTheVariablesThatFit()
{
    m_dock->selectComponent(0); // Clamp, a double-acting cylinder
    QCOMPARE(m_dock->nameEdit()->text(), QStringLiteral("Clamp"));
    QComboBox* extend = m_dock->roleCombo(QStringLiteral("extend"));
    QComboBox* extended = m_dock->roleCombo(QStringLiteral("extended"));
    QVERIFY(extend && extended && m_dock->roleCombo(QStringLiteral("retract")));
    QVERIFY(!m_dock->roleCombo(QStringLiteral("run")));
    QCOMPARE(extend->currentText(), QStringLiteral("ClampOut"));
    QCOMPARE(extended->currentText(), QStringLiteral("Clamped"));
    const auto check = [this](QComboBox* combo, core::VariableKind kind) {
        QCOMPARE(combo->itemData(0).toString(), QString()); // "(not wired)"
        for (int i = 1; i < combo->count(); ++i) {
            const core::Variable* variable = m_document->model().variable(combo->itemText(i).toStdString());
            QVERIFY(variable);
            QCOMPARE(variable->type, core::IecType::Bool);
            QCOMPARE(variable->kind, kind);
        }
    };
    check(extend, core::VariableKind::Output);
    check(extended, core::VariableKind::Input);
    QVERIFY(extend->findText(QStringLiteral("Spindle")) > 0);    // an output
    QVERIFY(extend->findText(QStringLiteral("DrillHigh")) < 0);  // an input
    QVERIFY(extend->findText(QStringLiteral("PartCount")) < 0);  // not BOOL
    QVERIFY(extended->findText(QStringLiteral("DrillHigh")) > 0);

    m_dock->selectComponent(3); // Magazine, a part source
    QVERIFY(m_dock->conveyorCombo());
    QCOMPARE(m_dock->conveyorCombo()->currentText(), QStringLiteral("Infeed"));
    QCOMPARE(m_dock->parameterSpin(QStringLiteral("parts"))->value(), 10);
    m_dock->selectComponent(4); // the emergency stop
    QCOMPARE(m_dock->contactCombo()->currentText(), QStringLiteral("Normally closed"));
}

void TestMachineDock::wiringIsOneUndoableCommand()
{
    m_dock->selectComponent(0);
    chooseInCombo(m_dock->roleCombo(QStringLiteral("extended")), QStringLiteral("DrillLow"));
    QCOMPARE(std::string(machine().components[0].signal("extended")), std::string("DrillLow"));
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Edit Clamp"));
    // The form shows the model after the change.
    QCOMPARE(m_dock->roleCombo(QStringLiteral("extended"))->currentText(), QStringLiteral("DrillLow"));
    chooseInCombo(m_dock->roleCombo(QStringLiteral("extended")), QStringLiteral("(not wired)"));
    QCOMPARE(std::string(machine().components[0].signal("extended")), std::string());
    QCOMPARE(m_document->undoStack()->count(), 2); // another role's command, another field
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QCOMPARE(std::string(machine().components[0].signal("extended")), std::string("Clamped"));

    m_dock->selectComponent(6); // Stop, a push button
    chooseInCombo(m_dock->contactCombo(), QStringLiteral("Normally closed"));
    QCOMPARE(machine().components[6].contact, core::machine::Contact::NormallyClosed);
    m_dock->nameEdit()->setText(QStringLiteral("StopButtonPanel"));
    emit m_dock->nameEdit()->editingFinished();
    QCOMPARE(machine().components[6].name, std::string("StopButtonPanel"));
    // A name the machine already has is refused: nothing changes, the form shows the model's.
    m_dock->nameEdit()->setText(QStringLiteral("clamp"));
    emit m_dock->nameEdit()->editingFinished();
    QCOMPARE(machine().components[6].name, std::string("StopButtonPanel"));
}

void TestMachineDock::timeStepsMergeIntoOneCommand()
{
    m_dock->selectComponent(1); // DrillHead
    QSpinBox* extend = m_dock->parameterSpin(QStringLiteral("extendMs"));
    QVERIFY(extend);
    QCOMPARE(extend->value(), 1500);
    extend->setValue(1600);
    m_dock->parameterSpin(QStringLiteral("extendMs"))->setValue(1700);
    QCOMPARE(machine().components[1].parameter("extendMs"), std::int64_t{1700});
    QCOMPARE(m_document->undoStack()->count(), 1);
    m_document->undoStack()->undo();
    QCOMPARE(machine().components[1].parameter("extendMs"), std::int64_t{1500});
}

void TestMachineDock::renamingAConveyorKeepsItsSources()
{
    m_dock->selectComponent(2); // Infeed
    m_dock->nameEdit()->setText(QStringLiteral("Belt"));
    emit m_dock->nameEdit()->editingFinished();
    QCOMPARE(machine().components[2].name, std::string("Belt"));
    QCOMPARE(machine().components[3].conveyor, std::string("Belt"));
    m_document->undoStack()->undo();
    QCOMPARE(machine().components[3].conveyor, std::string("Infeed"));
}

void TestMachineDock::lockedWhileSimulating()
{
    QVERIFY(m_dock->widget()->isEnabled());
    m_document->setReadOnly(true);
    QVERIFY(!m_dock->widget()->isEnabled());
    m_document->setReadOnly(false);
    QVERIFY(m_dock->widget()->isEnabled());
}

void TestMachineDock::firstComponentBringsTheMachineTab()
{
    std::unique_ptr<Translators> translators;
    auto window = editortest::showEnglishMainWindow(translators);
    QVERIFY(!window->machineTab()->view());
    auto* dock = window->findChild<MachineDock*>(QStringLiteral("machineDock"));
    QVERIFY(dock);
    // Closed at first, opened from View > Machine.
    QVERIFY(dock->isHidden());
    auto* viewMenu = window->findChild<QMenu*>(QStringLiteral("viewMenu"));
    QVERIFY(viewMenu && viewMenu->actions().contains(dock->toggleViewAction()));
    dock->toggleViewAction()->trigger();
    QVERIFY(dock->isVisible());
    // Tabbed with Variables, after a Reset Layout too.
    window->findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
    QVERIFY(window->tabifiedDockWidgets(dock).contains(window->findChild<QDockWidget*>(QStringLiteral("variablesDock"))));
    QVERIFY(dock->isVisible());
    dock->kindCombo()->setCurrentIndex(dock->kindCombo()->findText(QStringLiteral("Lamp")));
    dock->addComponent();
    QVERIFY(window->machineTab()->view());
    window->document()->undoStack()->undo();
    QVERIFY(!window->machineTab()->view());
    window->document()->undoStack()->setClean();
}

// The checks are the core's; the dock's edits show up in the Problems dock.
void TestMachineDock::machineChecksAreInTheProblemsDock()
{
    std::unique_ptr<Translators> translators;
    auto window = editortest::showEnglishMainWindow(translators);
    QString error;
    QVERIFY2(window->document()->load(QStringLiteral(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json"), &error),
             qPrintable(error));
    auto* dock = window->findChild<MachineDock*>(QStringLiteral("machineDock"));
    auto* problems = window->findChild<ProblemsDock*>(QStringLiteral("problemsDock"));
    QVERIFY(dock && problems);
    const auto listed = [problems](const QString& code) {
        for (QTreeWidgetItemIterator it(problems->view()); *it; ++it) {
            if ((*it)->text(ProblemsDock::CodeColumn) == code)
                return true;
        }
        return false;
    };
    QVERIFY(!listed(QStringLiteral("GG607")));
    dock->kindCombo()->setCurrentIndex(dock->kindCombo()->findText(QStringLiteral("Lamp")));
    dock->addComponent(); // its lamp output not wired
    QTRY_VERIFY(listed(QStringLiteral("GG607")));
    dock->selectComponent(0);
    chooseInCombo(dock->roleCombo(QStringLiteral("extended")), QStringLiteral("DrillLow")); // DrillLow twice
    QTRY_VERIFY(listed(QStringLiteral("GG604")));
    window->document()->undoStack()->setClean();
}

QTEST_MAIN(TestMachineDock)
#include "test_machinedock.moc"
