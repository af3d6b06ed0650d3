// Every undo command: redo and undo change the model and emit the
// Document's typed signals; typing merges; failures never enter the stack.

#include "editor/commands/addvariablecommand.h"
#include "editor/commands/movevariablecommand.h"
#include "editor/commands/pastevariablescommand.h"
#include "editor/commands/removevariablecommand.h"
#include "editor/commands/renamevariablecommand.h"
#include "editor/commands/resetmodelcommand.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setcycletimecommand.h"
#include "editor/commands/setdialectcommand.h"
#include "editor/commands/setevolutionrulecommand.h"
#include "editor/commands/setinitialstepcommand.h"
#include "editor/commands/setmodelnamecommand.h"
#include "editor/commands/setnegatedcommand.h"
#include "editor/commands/setprioritycommand.h"
#include "editor/commands/setstepcommentcommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/commands/setsteptypecommand.h"
#include "editor/commands/settokenscommand.h"
#include "editor/commands/settransitionhiddencommand.h"
#include "editor/commands/setvariablecommentcommand.h"
#include "editor/commands/setvariabledefaultcommand.h"
#include "editor/commands/setvariablekindcommand.h"
#include "editor/commands/setvariabletypecommand.h"
#include "editor/document.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace editor;

namespace {

core::Variable variable(const std::string& name, core::IecType type = core::IecType::Bool)
{
    core::Variable v;
    v.name = name;
    v.type = type;
    return v;
}

// The ids of a source's transitions, in order (hidden ones included).
QStringList orderOf(const core::Model& model, const std::string& source)
{
    QStringList ids;
    for (const core::Transition* t : model.outgoing(source))
        ids << QString::fromStdString(t->id);
    return ids;
}

QStringList variableNames(const core::Model& model)
{
    QStringList names;
    for (const core::Variable& v : model.variables())
        names << QString::fromStdString(v.name);
    return names;
}

// The string arguments a spy has recorded, in order.
QStringList ids(const QSignalSpy& spy)
{
    QStringList result;
    for (const QList<QVariant>& arguments : spy)
        result << arguments.at(0).toString();
    return result;
}

void addVariables(Document& document, std::initializer_list<std::string> names)
{
    for (const std::string& name : names)
        QVERIFY(document.push(new AddVariableCommand(document, variable(name))));
    document.undoStack()->clear();
}

} // namespace

class TestCommands : public QObject {
    Q_OBJECT

private slots:
    void setStepType();
    void setInitialStep();
    void setStepHidden();
    void setStepCommentMerges();
    void setTransitionHidden();
    void setPriorityRestoresEveryOrder();
    void setConditionMergesTyping();
    void setConditionTypedBackLeavesNoStep();
    void setConditionDoesNotMergeAcrossSave();
    void setNegated();
    void setTokens();
    void failingCommandStaysOffTheStack();
    void failingCommandKeepsRedoHistory();
    void commandThatChangesNothingIsDropped();
    void addVariableAtIndex();
    void removeVariableRestoresPosition();
    void renameVariableUndoRestoresExactTexts();
    void setVariableType();
    void setVariableKind();
    void setVariableDefaultAndCommentMerge();
    void moveVariable();
    void resetModel();
    void settings();
    void setEvolutionRule();
    void pasteVariables();
};

void TestCommands::setStepType()
{
    Document document;
    QSignalSpy changed(&document, &Document::stepChanged);
    QVERIFY(document.push(new SetStepTypeCommand(document, "F1", core::StepType::Simple)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set F1 to simple step"));
    QCOMPARE(document.model().step("F1")->type, core::StepType::Simple);
    QCOMPARE(ids(changed), QStringList{"F1"});

    document.undoStack()->undo();
    QCOMPARE(document.model().step("F1")->type, core::StepType::Macro);
    QCOMPARE(changed.count(), 2);
    document.undoStack()->redo();
    QCOMPARE(document.model().step("F1")->type, core::StepType::Simple);

    QVERIFY(document.push(new SetStepTypeCommand(document, "A1", core::StepType::Macro)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set A1 to macro-step"));
}

void TestCommands::setInitialStep()
{
    Document document;
    QSignalSpy changed(&document, &Document::stepChanged);
    QVERIFY(document.push(new SetInitialStepCommand(document, "A1")));
    QCOMPARE(document.undoStack()->undoText(), QString("Make A1 the initial step"));
    QCOMPARE(document.model().initialStep().id, std::string("A1"));
    QVERIFY(ids(changed).contains("A1"));
    QVERIFY(ids(changed).contains("A6"));

    document.undoStack()->undo();
    QCOMPARE(document.model().initialStep().id, std::string("A6"));
    QVERIFY(!document.model().step("A1")->initial);
}

void TestCommands::setStepHidden()
{
    Document document;
    QSignalSpy changed(&document, &Document::stepChanged);
    QVERIFY(document.push(new SetStepHiddenCommand(document, "F2", true)));
    QCOMPARE(document.undoStack()->undoText(), QString("Hide step F2"));
    QVERIFY(document.model().step("F2")->hidden);
    QVERIFY(!document.model().isEffective("A1->F2"));
    QCOMPARE(ids(changed), QStringList{"F2"});

    document.undoStack()->undo();
    QVERIFY(!document.model().step("F2")->hidden);

    document.undoStack()->redo();
    QVERIFY(document.push(new SetStepHiddenCommand(document, "F2", false)));
    QCOMPARE(document.undoStack()->undoText(), QString("Show step F2"));
    QVERIFY(!document.model().step("F2")->hidden);
    document.undoStack()->undo();
    QVERIFY(document.model().step("F2")->hidden);
}

void TestCommands::setStepCommentMerges()
{
    Document document;
    QVERIFY(document.push(new SetStepCommentCommand(document, "F1", "P")));
    QVERIFY(document.push(new SetStepCommentCommand(document, "F1", "Pr")));
    QVERIFY(document.push(new SetStepCommentCommand(document, "F1", "Press")));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QString("Edit comment of F1"));
    QCOMPARE(document.model().step("F1")->comment, std::string("Press"));

    QVERIFY(document.push(new SetStepCommentCommand(document, "F2", "Run")));
    QCOMPARE(document.undoStack()->count(), 2); // another step: its own undo step

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(document.model().step("F1")->comment, std::string());
    QCOMPARE(document.model().step("F2")->comment, std::string());
}

void TestCommands::setTransitionHidden()
{
    Document document;
    QSignalSpy changed(&document, &Document::transitionChanged);
    QVERIFY(document.push(new SetTransitionHiddenCommand(document, "A1->F2", true)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Hide transition A1 → F2"));
    QVERIFY(document.model().transition("A1->F2")->hidden);
    QCOMPARE(ids(changed), QStringList{"A1->F2"});
    QVERIFY(document.push(new SetTransitionHiddenCommand(document, "A1->F2", false)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Show transition A1 → F2"));
    QVERIFY(!document.model().transition("A1->F2")->hidden);

    document.undoStack()->undo();
    QVERIFY(document.model().transition("A1->F2")->hidden);
    document.undoStack()->undo();
    QVERIFY(!document.model().transition("A1->F2")->hidden);
}

void TestCommands::setPriorityRestoresEveryOrder()
{
    Document document;
    // A hidden sibling keeps its place: only a full restore of the orders undoes exactly.
    QVERIFY(document.push(new SetTransitionHiddenCommand(document, "A1->F2", true)));
    const QStringList before{"A1->F4", "A1->F2", "A1->F1", "A1->F5"};
    QCOMPARE(orderOf(document.model(), "A1"), before);

    QSignalSpy changed(&document, &Document::transitionChanged);
    QVERIFY(document.push(new SetPriorityCommand(document, "A1->F5", 1)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Set priority of A1 → F5 to 1"));
    QCOMPARE(document.model().priority("A1->F5"), 1);
    QCOMPARE(document.model().priority("A1->F4"), 2);
    QVERIFY(ids(changed).contains("A1->F5"));
    QVERIFY(ids(changed).contains("A1->F4"));

    document.undoStack()->undo();
    QCOMPARE(orderOf(document.model(), "A1"), before);
    for (const core::Transition* t : document.model().outgoing("A1"))
        QCOMPARE(t->order, static_cast<int>(before.indexOf(QString::fromStdString(t->id))) + 1);

    document.undoStack()->redo();
    QCOMPARE(document.model().priority("A1->F5"), 1);

    // Out of range and not effective: refused.
    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetPriorityCommand(document, "A1->F5", 4)));
    QVERIFY(!document.push(new SetPriorityCommand(document, "A1->F2", 1)));
    QCOMPARE(failed.count(), 2);
}

void TestCommands::setConditionMergesTyping()
{
    Document document;
    QSignalSpy changed(&document, &Document::transitionChanged);
    for (const char* text : {"S", "St", "Sta", "Start"})
        QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", text)));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Edit condition of F1 → A2"));
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("Start"));
    QCOMPARE(changed.count(), 4);

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "Go")));
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "Start AND Go")));
    QCOMPARE(document.undoStack()->count(), 3); // not consecutive: no merge

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("Start"));
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string());
    document.undoStack()->undo();
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string());
    document.undoStack()->redo();
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("Start"));
}

void TestCommands::setConditionTypedBackLeavesNoStep()
{
    Document document;
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "X")));
    QVERIFY(document.isModified());
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "")));
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());
}

void TestCommands::setConditionDoesNotMergeAcrossSave()
{
    Document document;
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "Sta")));
    document.undoStack()->setClean(); // as a save does
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "Start")));
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    QVERIFY(!document.isModified());
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("Sta"));
}

void TestCommands::setNegated()
{
    Document document;
    QVERIFY(document.push(new SetNegatedCommand(document, "F1->D1", false)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Remove negation of F1 → D1"));
    QVERIFY(!document.model().transition("F1->D1")->negated);
    QVERIFY(document.push(new SetNegatedCommand(document, "F1->A2", true)));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Negate F1 → A2"));
    QVERIFY(document.model().transition("F1->A2")->negated);

    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(document.model().transition("F1->D1")->negated);
    QVERIFY(!document.model().transition("F1->A2")->negated);
}

void TestCommands::setTokens()
{
    Document document;
    addVariables(document, {"Stop", "Reset"});
    QSignalSpy changed(&document, &Document::transitionChanged);
    QVERIFY(document.push(new SetTokensCommand(document, "F1->A2", {"Stop"})));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Set tokens of F1 → A2"));
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string>{"Stop"});
    QCOMPARE(ids(changed), QStringList{"F1->A2"});
    QVERIFY(document.push(new SetTokensCommand(document, "F1->A2", {"Stop", "Reset"})));

    document.undoStack()->undo();
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string>{"Stop"});
    document.undoStack()->undo();
    QVERIFY(document.model().transition("F1->A2")->tokens.empty());
}

void TestCommands::failingCommandStaysOffTheStack()
{
    Document document;
    addVariables(document, {"Stop"});
    QSignalSpy failed(&document, &Document::editFailed);
    QSignalSpy changed(&document, &Document::transitionChanged);
    const std::uint64_t revision = document.model().revision();

    QVERIFY(!document.push(new SetTokensCommand(document, "F1->A2", {"Stop", "STOP"})));
    QCOMPARE(failed.count(), 1);
    QVERIFY(failed.at(0).at(0).toString().startsWith(QStringLiteral("Set tokens of F1 → A2: ")));
    QVERIFY(!document.push(new SetStepTypeCommand(document, "Z9", core::StepType::Macro)));
    QVERIFY(!document.push(new SetCycleTimeCommand(document, 0)));
    QVERIFY(!document.push(new AddVariableCommand(document, variable("STOP"))));
    QVERIFY(!document.push(new RenameVariableCommand(document, "Nothing", "Other")));
    QCOMPARE(failed.count(), 5);

    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());
    QCOMPARE(document.model().revision(), revision);
    QCOMPARE(changed.count(), 0);
}

void TestCommands::failingCommandKeepsRedoHistory()
{
    Document document;
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "TRUE")));
    document.undoStack()->undo();
    QVERIFY(document.undoStack()->canRedo());
    QVERIFY(!document.push(new SetCycleTimeCommand(document, -5)));
    QVERIFY(document.undoStack()->canRedo());
    document.undoStack()->redo();
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("TRUE"));
}

void TestCommands::commandThatChangesNothingIsDropped()
{
    Document document;
    QSignalSpy failed(&document, &Document::editFailed);
    QVERIFY(document.push(new SetStepTypeCommand(document, "F1", core::StepType::Macro))); // already macro
    QVERIFY(document.push(new SetInitialStepCommand(document, "A6")));
    QVERIFY(document.push(new ResetModelCommand(document)));
    QCOMPARE(document.undoStack()->count(), 0);
    QCOMPARE(failed.count(), 0);
    QVERIFY(!document.isModified());
}

void TestCommands::addVariableAtIndex()
{
    Document document;
    addVariables(document, {"A", "C"});
    QSignalSpy listChanged(&document, &Document::variablesChanged);
    QVERIFY(document.push(new AddVariableCommand(document, variable("B"), 1)));
    QCOMPARE(document.undoStack()->undoText(), QString("Add variable B"));
    QCOMPARE(variableNames(document.model()), (QStringList{"A", "B", "C"}));
    QCOMPARE(listChanged.count(), 1);

    document.undoStack()->undo();
    QCOMPARE(variableNames(document.model()), (QStringList{"A", "C"}));
    QCOMPARE(listChanged.count(), 2);
    document.undoStack()->redo();
    QCOMPARE(variableNames(document.model()), (QStringList{"A", "B", "C"}));

    QVERIFY(!document.push(new AddVariableCommand(document, variable("D"), 9)));
    QVERIFY(!document.push(new AddVariableCommand(document, variable(""))));
    QCOMPARE(document.undoStack()->count(), 1);
}

void TestCommands::removeVariableRestoresPosition()
{
    Document document;
    core::Variable speed = variable("Speed", core::IecType::Int);
    speed.defaultValue = "42";
    speed.comment = "rpm";
    QVERIFY(document.push(new AddVariableCommand(document, variable("Start"))));
    QVERIFY(document.push(new AddVariableCommand(document, speed)));
    QVERIFY(document.push(new AddVariableCommand(document, variable("Stop"))));

    QSignalSpy listChanged(&document, &Document::variablesChanged);
    QVERIFY(document.push(new RemoveVariableCommand(document, "SPEED")));
    QCOMPARE(document.undoStack()->undoText(), QString("Remove variable SPEED"));
    QCOMPARE(variableNames(document.model()), (QStringList{"Start", "Stop"}));
    QCOMPARE(listChanged.count(), 1);

    document.undoStack()->undo();
    QCOMPARE(variableNames(document.model()), (QStringList{"Start", "Speed", "Stop"}));
    QVERIFY(*document.model().variable("Speed") == speed);

    QVERIFY(!document.push(new RemoveVariableCommand(document, "Missing")));
}

void TestCommands::renameVariableUndoRestoresExactTexts()
{
    Document document;
    addVariables(document, {"Stop", "Go"});
    // Spelled three ways: renaming back would write "Stop" everywhere.
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "NOT stop AND Go")));
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "Go AND NOT STOP")));
    QVERIFY(document.push(new SetTokensCommand(document, "F1->A2", {"stop"})));
    QVERIFY(document.push(new SetConditionCommand(document, "A2->A1", "Go")));
    const core::Model before(document.model());

    QSignalSpy transitions(&document, &Document::transitionChanged);
    QSignalSpy variables(&document, &Document::variablesChanged);
    QVERIFY(document.push(new RenameVariableCommand(document, "STOP", "Halt")));
    QCOMPARE(document.undoStack()->undoText(), QString("Rename variable STOP to Halt"));
    QVERIFY(document.model().variable("Halt"));
    QVERIFY(!document.model().variable("Stop"));
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("NOT Halt AND Go"));
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("Go AND NOT Halt"));
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string>{"Halt"});
    QVERIFY(ids(transitions).contains("F1->A2"));
    QVERIFY(ids(transitions).contains("A1->F1"));
    QVERIFY(!ids(transitions).contains("A2->A1"));
    QVERIFY(variables.count() >= 1);

    document.undoStack()->undo();
    QVERIFY(document.model().sameContent(before));
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("NOT stop AND Go"));
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("Go AND NOT STOP"));
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string>{"stop"});
    QCOMPARE(document.model().variables().front().name, std::string("Stop"));

    document.undoStack()->redo();
    QCOMPARE(document.model().transition("A1->F1")->condition, std::string("Go AND NOT Halt"));

    QVERIFY(!document.push(new RenameVariableCommand(document, "Halt", "go"))); // taken, ignoring case
    QVERIFY(!document.push(new RenameVariableCommand(document, "Halt", "")));
}

void TestCommands::setVariableType()
{
    Document document;
    addVariables(document, {"Speed"});
    QSignalSpy changed(&document, &Document::variableChanged);
    QVERIFY(document.push(new SetVariableTypeCommand(document, "Speed", core::IecType::Int)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set type of Speed to INT"));
    QCOMPARE(document.model().variable("Speed")->type, core::IecType::Int);
    QCOMPARE(ids(changed), QStringList{"Speed"});
    document.undoStack()->undo();
    QCOMPARE(document.model().variable("Speed")->type, core::IecType::Bool);
}

void TestCommands::setVariableKind()
{
    Document document;
    addVariables(document, {"Valve", "Count"});
    QSignalSpy changed(&document, &Document::variableChanged);
    QVERIFY(document.push(new SetVariableKindCommand(document, "valve", core::VariableKind::Output)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set kind of valve to output"));
    QCOMPARE(document.model().variable("Valve")->kind, core::VariableKind::Output);
    QCOMPARE(ids(changed), QStringList{"Valve"});
    QVERIFY(document.push(new SetVariableKindCommand(document, "Count", core::VariableKind::Internal)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set kind of Count to internal"));
    QCOMPARE(document.undoStack()->count(), 2); // no merging: each is its own step

    document.undoStack()->undo();
    QCOMPARE(document.model().variable("Count")->kind, core::VariableKind::Input);
    document.undoStack()->undo();
    QCOMPARE(document.model().variable("Valve")->kind, core::VariableKind::Input);

    // The same kind again changes nothing and is dropped; an unknown name fails.
    QVERIFY(document.push(new SetVariableKindCommand(document, "Valve", core::VariableKind::Input)));
    QCOMPARE(document.undoStack()->index(), 0);
    QVERIFY(!document.push(new SetVariableKindCommand(document, "Nothing", core::VariableKind::Output)));
}

void TestCommands::setVariableDefaultAndCommentMerge()
{
    Document document;
    addVariables(document, {"Speed", "Count"});
    QVERIFY(document.push(new SetVariableTypeCommand(document, "Speed", core::IecType::Int)));
    document.undoStack()->clear();

    QVERIFY(document.push(new SetVariableDefaultCommand(document, "Speed", "1")));
    QVERIFY(document.push(new SetVariableDefaultCommand(document, "speed", "12"))); // same variable
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QString("Set default of Speed"));
    QCOMPARE(document.model().variable("Speed")->defaultValue, std::string("12"));

    QVERIFY(document.push(new SetVariableCommentCommand(document, "Speed", "r")));
    QVERIFY(document.push(new SetVariableCommentCommand(document, "Speed", "rpm")));
    QVERIFY(document.push(new SetVariableCommentCommand(document, "Count", "pieces")));
    QCOMPARE(document.undoStack()->count(), 3);
    QCOMPARE(document.undoStack()->undoText(), QString("Edit comment of Count"));

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(document.model().variable("Speed")->comment, std::string());
    QCOMPARE(document.model().variable("Speed")->defaultValue, std::string("12"));
    document.undoStack()->undo();
    QCOMPARE(document.model().variable("Speed")->defaultValue, std::string());
}

void TestCommands::moveVariable()
{
    Document document;
    addVariables(document, {"A", "B", "C"});
    QSignalSpy listChanged(&document, &Document::variablesChanged);
    QVERIFY(document.push(new MoveVariableCommand(document, "A", 2)));
    QCOMPARE(document.undoStack()->undoText(), QString("Move variable A"));
    QCOMPARE(variableNames(document.model()), (QStringList{"B", "C", "A"}));
    QCOMPARE(listChanged.count(), 1);
    document.undoStack()->undo();
    QCOMPARE(variableNames(document.model()), (QStringList{"A", "B", "C"}));
    QVERIFY(!document.push(new MoveVariableCommand(document, "A", 3)));
}

void TestCommands::resetModel()
{
    Document document;
    addVariables(document, {"Start"});
    QVERIFY(document.push(new SetStepHiddenCommand(document, "F6", true)));
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "Start")));
    const core::Model before(document.model());

    QSignalSpy reset(&document, &Document::modelReset);
    QVERIFY(document.push(new ResetModelCommand(document)));
    QCOMPARE(document.undoStack()->undoText(), QString("Reset to template"));
    QVERIFY(document.model().sameContent(core::Model()));
    QCOMPARE(reset.count(), 1);

    document.undoStack()->undo();
    QVERIFY(document.model().sameContent(before));
    QCOMPARE(reset.count(), 2);
    document.undoStack()->redo();
    QVERIFY(document.model().sameContent(core::Model()));
}

void TestCommands::settings()
{
    Document document;
    QSignalSpy changed(&document, &Document::settingsChanged);
    QVERIFY(document.push(new SetModelNameCommand(document, "P")));
    QVERIFY(document.push(new SetModelNameCommand(document, "Press")));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QString("Rename model"));
    QCOMPARE(document.model().settings().name, std::string("Press"));

    QVERIFY(document.push(new SetCycleTimeCommand(document, 10)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set cycle time to 10 ms"));
    QVERIFY(document.push(new SetDialectCommand(document, core::Dialect::Codesys)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set dialect to CODESYS"));
    QCOMPARE(document.model().settings().dialect, core::Dialect::Codesys);
    QCOMPARE(changed.count(), 4);

    document.undoStack()->undo();
    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(document.model().settings() == core::ModelSettings());
}

void TestCommands::setEvolutionRule()
{
    Document document;
    QSignalSpy changed(&document, &Document::settingsChanged);
    QVERIFY(document.push(new SetEvolutionRuleCommand(document, core::EvolutionRule::UntilStable)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set evolution rule to until stable"));
    QCOMPARE(document.model().settings().evolution, core::EvolutionRule::UntilStable);
    QCOMPARE(changed.count(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.model().settings().evolution, core::EvolutionRule::OneEvolutionPerScan);
    QVERIFY(document.model().settings() == core::ModelSettings());
    document.undoStack()->redo();
    QVERIFY(document.push(new SetEvolutionRuleCommand(document, core::EvolutionRule::OneEvolutionPerScan)));
    QCOMPARE(document.undoStack()->undoText(), QString("Set evolution rule to one evolution per scan"));
}

void TestCommands::pasteVariables()
{
    Document document;
    addVariables(document, {"Start", "Stop"});
    std::vector<core::Variable> copied{variable("Start"), variable("Speed", core::IecType::Int), variable("Start_2")};
    QVERIFY(document.push(new PasteVariablesCommand(document, copied, 1)));
    QCOMPARE(document.undoStack()->undoText(), QString("Paste 3 variables"));
    QCOMPARE(document.undoStack()->count(), 1);
    // Taken names get a free suffix; the positions follow the insertion point.
    QCOMPARE(variableNames(document.model()), (QStringList{"Start", "Start_2", "Speed", "Start_3", "Stop"}));
    QCOMPARE(document.model().variable("Speed")->type, core::IecType::Int);

    document.undoStack()->undo();
    QCOMPARE(variableNames(document.model()), (QStringList{"Start", "Stop"}));
    document.undoStack()->redo();
    QCOMPARE(variableNames(document.model()), (QStringList{"Start", "Start_2", "Speed", "Start_3", "Stop"}));

    // All or nothing: a name the model refuses leaves no partial paste.
    QVERIFY(!document.push(new PasteVariablesCommand(document, {variable("Fresh"), variable("")})));
    QCOMPARE(variableNames(document.model()).size(), 5);
    QVERIFY(!document.model().variable("Fresh"));

    QVERIFY(document.push(new PasteVariablesCommand(document, {variable("Alone")})));
    QCOMPARE(document.undoStack()->undoText(), QString("Paste variable Alone"));
}

QTEST_MAIN(TestCommands)
#include "test_commands.moc"
