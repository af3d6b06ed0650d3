// The undo commands of the PackML operations (editor/commands/packml/):
// redo and undo change the model and emit the Document's typed signals;
// typing merges; refusals never enter the stack.

#include "editor/commands/packml/addmodecommand.h"
#include "editor/commands/packml/packmlcommandtextcommands.h"
#include "editor/commands/packml/packmlmodetextcommands.h"
#include "editor/commands/packml/packmlsettingscommands.h"
#include "editor/commands/packml/removemodecommand.h"
#include "editor/commands/packml/setgrafcetchoicecommand.h"
#include "editor/commands/packml/setmodestatescommand.h"
#include "editor/document.h"

#include "core/templates/packml/packmlmodel.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace editor;
using core::packml::Command;
using core::packml::Edition;
using core::packml::GrafcetChoice;
using core::packml::State;
using core::packml::StateSet;

namespace {

const core::packml::Configuration& config(const Document& document)
{
    return *document.model().packml();
}

const core::packml::Mode& mode(const Document& document, int number)
{
    return *config(document).mode(number);
}

core::Grafcet oneStepGrafcet()
{
    core::Grafcet grafcet;
    core::GrafcetStep step;
    step.number = 1;
    step.initial = true;
    step.comment = "wait";
    grafcet.addStep(step);
    return grafcet;
}

} // namespace

class TestPackmlCommands : public QObject {
    Q_OBJECT

private slots:
    void commandConditionMergesTypingAndUndoes();
    void commandComment();
    void addModeTakesANameAndUndoes();
    void addModeRefusals();
    void removeModeRestoresEverything();
    void removeProductionIsRefused();
    void renameModeMergesAndRefuses();
    void modeCommentAndRequest();
    void modeStateLists();
    void grafcetChoiceOwnCreatesAndUndoRestores();
    void optionsTo2022AdoptCompleteCommand();
    void initialStateAndMode();
    void everyCommandFailsOnGemma();
};

void TestPackmlCommands::commandConditionMergesTypingAndUndoes()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QSignalSpy changed(&document, &Document::commandChanged);
    for (const char* text : {"Cmd_Hold O", "Cmd_Hold OR", "Cmd_Hold OR Jam"})
        QVERIFY(document.push(new SetCommandConditionCommand(document, "Hold", text)));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Edit condition of command Hold"));
    QCOMPARE(config(document).command(Command::Hold).condition, std::string("Cmd_Hold OR Jam"));
    QCOMPARE(changed.count(), 3);
    QCOMPARE(changed.last().at(0).toString(), QStringLiteral("Hold"));

    // Another command does not merge.
    QVERIFY(document.push(new SetCommandConditionCommand(document, "Stop", "FALSE")));
    QCOMPARE(document.undoStack()->count(), 2);

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(config(document).command(Command::Hold).condition, std::string("Cmd_Hold"));
    QCOMPARE(config(document).command(Command::Stop).condition, std::string("Cmd_Stop"));
    document.undoStack()->redo();
    QCOMPARE(config(document).command(Command::Hold).condition, std::string("Cmd_Hold OR Jam"));

    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetCommandConditionCommand(document, "Jump", "TRUE")));
    QCOMPARE(failed.count(), 1);
}

void TestPackmlCommands::commandComment()
{
    Document document(core::packml::newModel(Edition::Y2022));
    for (const char* text : {"From", "From the HMI"})
        QVERIFY(document.push(new SetCommandCommentCommand(document, "Complete", text)));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(config(document).command(Command::Complete).comment, std::string("From the HMI"));
    document.undoStack()->undo();
    QCOMPARE(config(document).command(Command::Complete).comment, std::string());
}

void TestPackmlCommands::addModeTakesANameAndUndoes()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QCOMPARE(AddModeCommand::firstFreeUserMode(document.model()), 4);
    QCOMPARE(AddModeCommand::suggestedName(document.model(), 4), QStringLiteral("Mode4"));
    QSignalSpy modes(&document, &Document::modesChanged);
    QVERIFY(document.push(new AddModeCommand(document, 4, "Cleaning")));
    QCOMPARE(modes.count(), 1);
    QCOMPARE(mode(document, 4).name, std::string("Cleaning"));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Add mode 4 Cleaning"));
    QCOMPARE(AddModeCommand::firstFreeUserMode(document.model()), 5);
    QVERIFY(document.push(new AddModeCommand(document, 17, "Changeover")));
    QCOMPARE(AddModeCommand::firstFreeUserMode(document.model()), 5);

    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(!config(document).mode(4));
    QCOMPARE(config(document).modes.size(), std::size_t(3));
    document.undoStack()->redo();
    QCOMPARE(mode(document, 4).name, std::string("Cleaning"));

    // A base mode removed comes back without a name.
    QVERIFY(document.push(new RemoveModeCommand(document, 2)));
    QVERIFY(document.push(new AddModeCommand(document, 2)));
    QCOMPARE(mode(document, 2).displayName(), std::string_view("Maintenance"));
}

void TestPackmlCommands::addModeRefusals()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new AddModeCommand(document, 40, "Far")));       // outside 1..31
    QVERIFY(!document.push(new AddModeCommand(document, 3, "Again")));      // has it; base modes take no name
    QVERIFY(!document.push(new AddModeCommand(document, 5, "manual")));     // Manual's, ignoring case
    QVERIFY(!document.push(new AddModeCommand(document, 5, "State")));      // reserved (§5.3)
    QVERIFY(!document.push(new AddModeCommand(document, 5, "Manual_Execute"))); // a generated instance
    QVERIFY(!document.push(new AddModeCommand(document, 5, "2fast")));      // no identifier
    QVERIFY(!document.push(new AddModeCommand(document, 5, "")));           // a user mode has a name
    QCOMPARE(failed.count(), 7);
    QCOMPARE(document.undoStack()->count(), 0);
    QCOMPARE(config(document).modes.size(), std::size_t(3));
    QVERIFY(failed.at(0).at(0).toString().startsWith(QStringLiteral("Add mode 40 Far: ")));

    // Every number taken: no free user mode.
    for (int number = 4; number <= 31; ++number)
        QVERIFY(document.push(new AddModeCommand(document, number, QStringLiteral("User%1").arg(number))));
    QCOMPARE(AddModeCommand::firstFreeUserMode(document.model()), 0);
}

void TestPackmlCommands::removeModeRestoresEverything()
{
    core::Model model = core::packml::newModel(Edition::Y2015);
    QVERIFY(model.addMode(4, "Cleaning"));
    QVERIFY(model.setModeComment(4, "CIP"));
    QVERIFY(model.setModeRequest(4, "KeyClean"));
    QVERIFY(model.setModeDisabled(4, StateSet{State::Holding}));
    QVERIFY(model.setModeChangeStates(4, StateSet{State::Stopped}));
    QVERIFY(model.setGrafcet(core::packml::grafcetKey(4, State::Execute), oneStepGrafcet()));
    QVERIFY(model.setGrafcetChoice(3, State::Execute, GrafcetChoice::sameAs(4)));
    QVERIFY(model.setPackMLInitialMode(4));
    Document document(model);
    const core::packml::Configuration before = config(document);

    QVERIFY(document.push(new RemoveModeCommand(document, 4)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove mode 4 Cleaning"));
    QVERIFY(!config(document).mode(4));
    QVERIFY(!document.model().grafcet("4/Execute"));
    QCOMPARE(mode(document, 3).grafcetChoice(State::Execute), GrafcetChoice::none());
    QCOMPARE(config(document).initialMode, 1); // back to Production

    document.undoStack()->undo();
    QVERIFY(config(document) == before);
    QVERIFY(document.model().grafcet("4/Execute"));
    QCOMPARE(document.model().grafcet("4/Execute")->steps().front().comment, std::string("wait"));
    QVERIFY(document.model().invariantViolations().empty());
    document.undoStack()->redo();
    QVERIFY(!config(document).mode(4));
    document.undoStack()->undo();
    QVERIFY(config(document) == before);
}

void TestPackmlCommands::removeProductionIsRefused()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new RemoveModeCommand(document, 1)));
    QVERIFY(!document.push(new RemoveModeCommand(document, 9))); // no such mode
    QCOMPARE(failed.count(), 2);
    QVERIFY(config(document).mode(1));
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestPackmlCommands::renameModeMergesAndRefuses()
{
    core::Model model = core::packml::newModel(Edition::Y2015);
    QVERIFY(model.addMode(4, "Mode4"));
    Document document(model);
    for (const char* text : {"C", "Cl", "Clean"})
        QVERIFY(document.push(new RenameModeCommand(document, 4, text)));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Rename mode 4 Mode4"));
    QCOMPARE(mode(document, 4).name, std::string("Clean"));

    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new RenameModeCommand(document, 4, "Mode")));       // reserved
    QVERIFY(!document.push(new RenameModeCommand(document, 4, "PRODUCTION"))); // taken, ignoring case
    QVERIFY(!document.push(new RenameModeCommand(document, 4, "a__b")));       // no identifier
    QVERIFY(!document.push(new RenameModeCommand(document, 3, "Hand")));       // base names are fixed
    QCOMPARE(failed.count(), 4);
    QCOMPARE(mode(document, 4).name, std::string("Clean"));
    QCOMPARE(document.undoStack()->count(), 1);

    // Its own name, in another case, is no duplicate.
    QVERIFY(document.push(new RenameModeCommand(document, 4, "CLEAN")));
    document.undoStack()->undo();
    QCOMPARE(mode(document, 4).name, std::string("Mode4"));
}

void TestPackmlCommands::modeCommentAndRequest()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QSignalSpy changed(&document, &Document::modeChanged);
    for (const char* text : {"Key", "KeyManual"})
        QVERIFY(document.push(new SetModeRequestCommand(document, 3, text)));
    QVERIFY(document.push(new SetModeCommentCommand(document, 3, "Jogging")));
    QCOMPARE(document.undoStack()->count(), 2);
    QCOMPARE(mode(document, 3).request, std::string("KeyManual"));
    QCOMPARE(mode(document, 3).comment, std::string("Jogging"));
    QCOMPARE(changed.last().at(0).toInt(), 3);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(mode(document, 3).request, std::string());
    QCOMPARE(mode(document, 3).comment, std::string());
}

void TestPackmlCommands::modeStateLists()
{
    Document document(core::packml::newModel(Edition::Y2015));
    const StateSet disabled{State::Held, State::Holding, State::Unholding};
    QVERIFY(document.push(new SetModeStatesCommand(document, 3, SetModeStatesCommand::List::Disabled, disabled)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Change disabled states of mode 3 Manual"));
    const StateSet changes{State::Stopped, State::Execute};
    QVERIFY(document.push(new SetModeStatesCommand(document, 3, SetModeStatesCommand::List::ModeChange, changes)));
    QVERIFY(mode(document, 3).disabled == disabled);
    QVERIFY(mode(document, 3).modeChange == changes);
    document.undoStack()->undo();
    QVERIFY((mode(document, 3).modeChange == StateSet{State::Stopped, State::Idle, State::Aborted}));
    document.undoStack()->undo();
    QVERIFY(mode(document, 3).disabled.empty());

    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetModeStatesCommand(document, 8, SetModeStatesCommand::List::Disabled, disabled)));
    QCOMPARE(failed.count(), 1);
}

void TestPackmlCommands::grafcetChoiceOwnCreatesAndUndoRestores()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QSignalSpy grafcets(&document, &Document::grafcetChanged);
    QVERIFY(document.push(new SetGrafcetChoiceCommand(document, 1, State::Starting, GrafcetChoice::own())));
    QVERIFY(document.model().grafcet("1/Starting"));
    QCOMPARE(grafcets.count(), 1);
    QVERIFY(document.push(new SetGrafcetChoiceCommand(document, 3, State::Starting, GrafcetChoice::sameAs(1))));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Run in Starting of mode 3 Manual the GRAFCET of mode 1"));
    QCOMPARE(document.model().effectiveGrafcet("3/Starting"), document.model().grafcet("1/Starting"));

    // Leaving Own removes a GRAFCET with content; undo brings it back whole.
    core::GrafcetStep step;
    step.number = 7;
    step.initial = true;
    QVERIFY(document.modelForCommands().addGrafcetStep("1/Starting", step));
    QVERIFY(document.push(new SetGrafcetChoiceCommand(document, 1, State::Starting, GrafcetChoice::none())));
    QVERIFY(!document.model().grafcet("1/Starting"));
    document.undoStack()->undo();
    QVERIFY(document.model().grafcet("1/Starting"));
    QVERIFY(document.model().grafcet("1/Starting")->step(7));
    QCOMPARE(mode(document, 1).grafcetChoice(State::Starting), GrafcetChoice::own());
    QVERIFY(document.model().invariantViolations().empty());

    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetGrafcetChoiceCommand(document, 1, State::Idle, GrafcetChoice::own())));
    QCOMPARE(failed.count(), 1);
}

void TestPackmlCommands::optionsTo2022AdoptCompleteCommand()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QVERIFY(document.model().variableIndex("Cmd_Complete") < 0);
    core::packml::Options options = core::packml::defaultOptions(Edition::Y2022);
    QSignalSpy settings(&document, &Document::packmlSettingsChanged);
    QVERIFY(document.push(new SetPackmlOptionsCommand(document, options)));
    QCOMPARE(settings.count(), 1);
    QVERIFY(config(document).options == options);
    QCOMPARE(config(document).command(Command::Complete).condition, std::string("Cmd_Complete"));
    QVERIFY(document.model().variableIndex("Cmd_Complete") >= 0);
    QCOMPARE(document.undoStack()->count(), 1);

    document.undoStack()->undo();
    QVERIFY(config(document).options == core::packml::defaultOptions(Edition::Y2015));
    QCOMPARE(config(document).command(Command::Complete).condition, std::string());
    QVERIFY(document.model().variableIndex("Cmd_Complete") < 0);

    // A Complete condition already written is kept, and nothing is declared.
    QVERIFY(document.modelForCommands().setCommandCondition(Command::Complete, "BatchDone"));
    QVERIFY(document.push(new SetPackmlOptionsCommand(document, options)));
    QCOMPARE(config(document).command(Command::Complete).condition, std::string("BatchDone"));
    QVERIFY(document.model().variableIndex("Cmd_Complete") < 0);
}

void TestPackmlCommands::initialStateAndMode()
{
    Document document(core::packml::newModel(Edition::Y2015));
    QVERIFY(document.push(new SetPackmlInitialStateCommand(document, State::Aborted)));
    QVERIFY(document.push(new SetPackmlInitialModeCommand(document, 3)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Set initial mode to 3 Manual"));
    QCOMPARE(config(document).initialState, State::Aborted);
    QCOMPARE(config(document).initialMode, 3);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(config(document).initialState, State::Stopped);
    QCOMPARE(config(document).initialMode, 1);

    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetPackmlInitialModeCommand(document, 9))); // not a mode of the model
    QCOMPARE(failed.count(), 1);
}

void TestPackmlCommands::everyCommandFailsOnGemma()
{
    Document document;
    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetCommandConditionCommand(document, "Hold", "x")));
    QVERIFY(!document.push(new AddModeCommand(document, 4, "Clean")));
    QVERIFY(!document.push(new RemoveModeCommand(document, 3)));
    QVERIFY(!document.push(new SetModeRequestCommand(document, 3, "x")));
    QVERIFY(!document.push(new SetModeStatesCommand(document, 3, SetModeStatesCommand::List::Disabled, {})));
    QVERIFY(!document.push(new SetGrafcetChoiceCommand(document, 1, State::Execute, GrafcetChoice::own())));
    QVERIFY(!document.push(new SetPackmlOptionsCommand(document, {})));
    QVERIFY(!document.push(new SetPackmlInitialStateCommand(document, State::Idle)));
    QVERIFY(!document.push(new SetPackmlInitialModeCommand(document, 1)));
    QCOMPARE(failed.count(), 9);
    QCOMPARE(document.undoStack()->count(), 0);
}

QTEST_MAIN(TestPackmlCommands)
#include "test_packmlcommands.moc"
