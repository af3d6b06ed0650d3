// The Document: signals, diagnostics, the modified flag, files; and the Selection.

#include "editor/commands/addvariablecommand.h"
#include "editor/commands/renamevariablecommand.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setinitialstepcommand.h"
#include "editor/commands/setreceptivitycommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/document.h"
#include "editor/selection.h"

#include "core/checks/checks.h"
#include "core/formats/gggeneratorformat.h"
#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlmodel.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>

using namespace editor;

namespace {

bool hasCode(const std::vector<core::Diagnostic>& diagnostics, const std::string& code)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [&](const core::Diagnostic& d) { return d.code == code; });
}

// The template whose F1 (a macro-step) has 1 --Go--> 2 (N Lamp, S Complete)
// --NOT Go--> 1, over Go (input) and Lamp (output).
core::Model nestedModel()
{
    core::Model model;
    model.addVariable({"Go", core::IecType::Bool, "", ""});
    core::Variable lamp{"Lamp", core::IecType::Bool, "", ""};
    lamp.kind = core::VariableKind::Output;
    model.addVariable(lamp);
    model.setStepType("F1", core::StepType::Macro);
    model.setGrafcet("F1", core::Grafcet());
    model.addGrafcetStep("F1", {1, true, "", {}});
    model.addGrafcetStep("F1", {2, false, "", {{core::ActionTiming::Continuous, "N Lamp"},
                                               {core::ActionTiming::OnActivation, "S Complete"}}});
    model.addGrafcetTransition("F1", {1, {1}, {2}, "Go"});
    model.addGrafcetTransition("F1", {2, {2}, {1}, "NOT Go"});
    return model;
}

void writeText(const QString& path, const QByteArray& text)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

// A document with one saved-worthy edit of each kind.
void edit(Document& document)
{
    core::Variable start;
    start.name = "Start";
    QVERIFY(document.push(new AddVariableCommand(document, start)));
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "Start")));
    QVERIFY(document.push(new SetStepHiddenCommand(document, "F6", true)));
}

} // namespace

class TestDocument : public QObject {
    Q_OBJECT

private slots:
    void startsWithTheTemplate();
    void diagnosticsFollowChanges();
    void signalsComeWhenTheEditIsComplete();
    void editsAroundCommandsAreCheckedLater();
    void receptivityEditsGiveTheWholeCheck();
    void modifiedFollowsUndoAndClean();
    void saveAndLoadRoundTrip();
    void failedLoadKeepsModelAndHistory();
    void loadSaysWhatItDidNotTakeOver();
    void loadsAPackmlModelAndSignalsItsEdits();
    void failedSaveKeepsModified();
    void replaceModelClearsHistory();
    void renameToAnInvalidNameIsRefused();
    void newFromTemplate();
    void selection();
    void packmlDiagnosticsBelongToTheirElements();
};

void TestDocument::startsWithTheTemplate()
{
    Document document;
    QVERIFY(document.model().sameContent(core::Model()));
    QVERIFY(!document.isModified());
    QCOMPARE(document.displayName(), QString("Untitled"));
    QVERIFY(document.filePath().isEmpty());
    QCOMPARE(document.fileFormat(), core::ModelFormat::Native);
    // The template's conditions are all empty: an error each.
    QVERIFY(!document.diagnostics().empty());
}

void TestDocument::diagnosticsFollowChanges()
{
    Document document;
    const ElementRef transition = ElementRef::transition("A1->F1");
    QVERIFY(hasCode(document.diagnosticsFor(transition), "GG202"));
    QVERIFY(document.hasProblems(transition));
    for (const core::Diagnostic& d : document.diagnosticsFor(transition))
        QCOMPARE(d.element, std::string("A1->F1"));

    // The checks must already be current when the typed signal arrives.
    bool currentOnSignal = false;
    connect(&document, &Document::transitionChanged, this, [&](const QString& id) {
        currentOnSignal = id == "A1->F1" && !hasCode(document.diagnosticsFor(transition), "GG202");
    });
    QSignalSpy diagnosticsChanged(&document, &Document::diagnosticsChanged);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(currentOnSignal);
    QCOMPARE(diagnosticsChanged.count(), 1);
    QVERIFY(!hasCode(document.diagnosticsFor(transition), "GG202"));

    document.undoStack()->undo();
    QCOMPARE(diagnosticsChanged.count(), 2);
    QVERIFY(hasCode(document.diagnosticsFor(transition), "GG202"));

    // Variables match ignoring case, as IEC names do.
    core::Variable bad;
    bad.name = "Speed";
    bad.type = core::IecType::Sint;
    bad.defaultValue = "300";
    QVERIFY(document.push(new AddVariableCommand(document, bad)));
    QVERIFY(document.hasProblems(ElementRef::variable("SPEED")));
    QVERIFY(!document.hasProblems(ElementRef()));
}

void TestDocument::signalsComeWhenTheEditIsComplete()
{
    Document document;
    // The model has no initial step for a moment inside setInitialStep.
    QStringList seen;
    connect(&document, &Document::stepChanged, this, [&](const QString& id) {
        seen << id + "/" + QString::fromStdString(document.model().initialStep().id);
    });
    QVERIFY(document.push(new SetInitialStepCommand(document, "A1")));
    QCOMPARE(seen, (QStringList{"A6/A1", "A1/A1"}));
    seen.clear();
    document.undoStack()->undo();
    QCOMPARE(seen, (QStringList{"A1/A6", "A6/A6"}));

    // A rename changes many elements; each is announced once, after all of them.
    core::Variable stop;
    stop.name = "Stop";
    QVERIFY(document.push(new AddVariableCommand(document, stop)));
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "Stop")));
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "NOT Stop")));
    QStringList conditions;
    connect(&document, &Document::transitionChanged, this, [&](const QString& id) {
        conditions << id + "=" + QString::fromStdString(document.model().transition("F1->A2")->condition);
    });
    QSignalSpy variables(&document, &Document::variablesChanged);
    QSignalSpy diagnosticsChanged(&document, &Document::diagnosticsChanged);
    QVERIFY(document.push(new RenameVariableCommand(document, "Stop", "Halt")));
    QCOMPARE(conditions, (QStringList{"A1->F1=Halt", "F1->A2=Halt"}));
    QCOMPARE(variables.count(), 1);
    QVERIFY(diagnosticsChanged.count() <= 1); // once for the whole edit, if at all
}

void TestDocument::renameToAnInvalidNameIsRefused()
{
    Document document;
    core::Variable stop;
    stop.name = "Stop";
    QVERIFY(document.push(new AddVariableCommand(document, stop)));
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "Stop OR NOT Stop")));
    const core::Model before(document.model());
    const int historySize = document.undoStack()->count();
    QSignalSpy failed(&document, &Document::editFailed);

    QVERIFY(!document.push(new RenameVariableCommand(document, "Stop", "Stop 2")));
    QCOMPARE(failed.count(), 1);
    const QString message = failed.front().at(0).toString();
    QVERIFY2(message.contains("'Stop 2' is not a valid IEC 61131-3 identifier"), qPrintable(message));
    QVERIFY(!document.push(new RenameVariableCommand(document, "Stop", "TRUE"))); // a keyword
    QVERIFY2(failed.back().at(0).toString().contains("keyword"), qPrintable(failed.back().at(0).toString()));
    QVERIFY(document.model().sameContent(before));
    QCOMPARE(document.undoStack()->count(), historySize);

    // Nor around the commands: the model itself refuses.
    const core::Status status = document.modelForCommands().renameVariable("Stop", "Stop 2");
    QVERIFY(!status);
    QCOMPARE(status.code, std::string("invalid-name"));
    QVERIFY(document.model().sameContent(before));
}

// A receptivity edit is re-checked incrementally (core/checks/incrementalcheck.h):
// typed, undone, redone, made around the commands or after another kind of
// edit, the diagnostics are those of the whole check.
void TestDocument::receptivityEditsGiveTheWholeCheck()
{
    Document document(nestedModel());
    const auto current = [&] { return document.diagnostics() == core::checkModel(document.model()); };
    QVERIFY(current());
    QVERIFY(!hasCode(document.diagnostics(), "GG305")); // Go is read by F1's receptivities
    QSignalSpy diagnosticsChanged(&document, &Document::diagnosticsChanged);

    // Typing "Ghost" over "Go": GG403 on T1, and Go is still read by T2.
    for (const char* typed : {"G", "Gh", "Gho", "Ghost"})
        QVERIFY(document.push(new SetReceptivityCommand(document, "F1", 1, QString::fromLatin1(typed))));
    QVERIFY(current());
    QVERIFY(hasCode(document.diagnostics(), "GG403"));
    QVERIFY(diagnosticsChanged.count() >= 1);

    // T2 no longer reads Go either: Go becomes unused.
    QVERIFY(document.push(new SetReceptivityCommand(document, "F1", 2, "TRUE")));
    QVERIFY(current());
    QVERIFY(hasCode(document.diagnostics(), "GG305"));
    document.undoStack()->undo();
    QVERIFY(current());
    QVERIFY(!hasCode(document.diagnostics(), "GG305"));
    document.undoStack()->redo();
    QVERIFY(current());

    // Declaring Ghost (a whole check), then reading it under an edge.
    core::Variable ghost;
    ghost.name = "Ghost";
    QVERIFY(document.push(new AddVariableCommand(document, ghost)));
    QVERIFY(current());
    QVERIFY(!hasCode(document.diagnostics(), "GG403"));
    QVERIFY(document.push(new SetReceptivityCommand(document, "F1", 2, "RE Ghost AND")));
    QVERIFY(current());
    QVERIFY(hasCode(document.diagnostics(), "GG401"));

    // Around the commands: checked once control is back in the event loop.
    const int before = diagnosticsChanged.count();
    QVERIFY(document.modelForCommands().setReceptivity("F1", 2, "NOT Go"));
    QTRY_VERIFY(diagnosticsChanged.count() > before);
    QVERIFY(current());
    QVERIFY(!hasCode(document.diagnostics(), "GG401"));
}

void TestDocument::editsAroundCommandsAreCheckedLater()
{
    Document document;
    QSignalSpy transitions(&document, &Document::transitionChanged);
    QSignalSpy diagnosticsChanged(&document, &Document::diagnosticsChanged);
    QVERIFY(document.modelForCommands().setCondition("A1->F1", "TRUE"));
    QVERIFY(document.modelForCommands().setInitialStep("A1")); // no check mid-operation
    QCOMPARE(transitions.count(), 1);
    QCOMPARE(diagnosticsChanged.count(), 0);
    QTRY_COMPARE(diagnosticsChanged.count(), 1);
    QVERIFY(!hasCode(document.diagnosticsFor(ElementRef::transition("A1->F1")), "GG202"));
}

void TestDocument::modifiedFollowsUndoAndClean()
{
    Document document;
    QSignalSpy modified(&document, &Document::modifiedChanged);
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F1", "TRUE")));
    QVERIFY(document.isModified());
    QCOMPARE(modified.count(), 1);
    QCOMPARE(modified.last().at(0).toBool(), true);

    document.undoStack()->undo();
    QVERIFY(!document.isModified());
    QCOMPARE(modified.last().at(0).toBool(), false);

    document.undoStack()->redo();
    QVERIFY(document.isModified());
    document.undoStack()->setClean();
    QVERIFY(!document.isModified());
    QCOMPARE(modified.count(), 4);
    document.undoStack()->undo(); // before the saved state: modified again
    QVERIFY(document.isModified());
}

void TestDocument::saveAndLoadRoundTrip()
{
    QTemporaryDir directory;
    QVERIFY(directory.isValid());
    const QString path = directory.filePath("press.ggs.json");

    Document document;
    edit(document);
    QSignalSpy pathChanged(&document, &Document::filePathChanged);
    QSignalSpy modified(&document, &Document::modifiedChanged);
    QString error;
    QVERIFY2(document.save(path, &error), qPrintable(error));
    QVERIFY(error.isEmpty());
    QVERIFY(!document.isModified());
    QCOMPARE(modified.count(), 1);
    QCOMPARE(document.filePath(), path);
    QCOMPARE(pathChanged.count(), 1);
    QCOMPARE(document.displayName(), QString("press.ggs.json"));
    QVERIFY(document.undoStack()->canUndo()); // saving keeps the history

    Document opened;
    QSignalSpy reset(&opened, &Document::modelReset);
    QVERIFY2(opened.load(path, &error), qPrintable(error));
    QCOMPARE(reset.count(), 1);
    QVERIFY(opened.model().sameContent(document.model()));
    QVERIFY(!opened.isModified());
    QCOMPARE(opened.filePath(), path);
    QCOMPARE(opened.fileFormat(), core::ModelFormat::Native);
    QCOMPARE(opened.undoStack()->count(), 0);
}

// A GG-Generator file carrying GG Studio's verification properties used to
// open without a word, and the properties were gone.
// A PackML model (format 3.0) opens like a GEMMA one; its edits come out as
// the PackML signals, after the checks.
void TestDocument::loadsAPackmlModelAndSignalsItsEdits()
{
    QTemporaryDir directory;
    const QString packml = directory.filePath("filler.json");
    QVERIFY(core::saveModelFile(core::packml::newModel(core::packml::Edition::Y2022), packml.toStdString(),
                                core::ModelFormat::Native));
    Document document;
    QString error;
    QVERIFY2(document.load(packml, &error), qPrintable(error));
    QVERIFY(document.model().packml());
    QCOMPARE(document.model().packml()->options.edition, core::packml::Edition::Y2022);
    QCOMPARE(document.filePath(), packml);

    QSignalSpy command(&document, &Document::commandChanged);
    QSignalSpy modes(&document, &Document::modesChanged);
    QSignalSpy mode(&document, &Document::modeChanged);
    QSignalSpy settings(&document, &Document::packmlSettingsChanged);
    core::Model& model = document.modelForCommands();
    QVERIFY(model.setCommandCondition(core::packml::Command::Start, "Cmd_Start AND Cmd_Reset"));
    QVERIFY(model.addMode(4, "Cleaning"));
    QVERIFY(model.setModeComment(4, "CIP"));
    QVERIFY(model.setPackMLInitialMode(4));
    QTRY_COMPARE(command.count(), 1);
    QCOMPARE(command.first().first().toString(), QStringLiteral("Start"));
    QCOMPARE(modes.count(), 1);
    QVERIFY(!mode.isEmpty());
    QCOMPARE(mode.last().first().toInt(), 4); // the comment
    QCOMPARE(settings.count(), 1);
}

void TestDocument::loadSaysWhatItDidNotTakeOver()
{
    QTemporaryDir directory;
    QVERIFY(directory.isValid());
    const QString path = directory.filePath("mixed.json");
    std::string text = core::saveGGGeneratorJson(core::Model());
    text.insert(text.rfind('}'), ", \"properties\": [{\"text\": \"never A1 AND F1\"}]");
    writeText(path, QByteArray::fromStdString(text));

    Document document;
    QString error;
    QStringList warnings{"stale"};
    QVERIFY2(document.load(path, &error, &warnings), qPrintable(error));
    QCOMPARE(warnings, QStringList{path + ": /properties: warning: the verification properties (1) are not loaded: "
                                          "a GG-Generator file has no place for them"});

    const QString native = directory.filePath("native.ggs.json");
    QVERIFY2(document.save(native, &error), qPrintable(error));
    QVERIFY2(document.load(native, &error, &warnings), qPrintable(error));
    QVERIFY(warnings.isEmpty());
}

void TestDocument::failedLoadKeepsModelAndHistory()
{
    QTemporaryDir directory;
    QVERIFY(directory.isValid());
    const QString broken = directory.filePath("broken.ggs.json");
    writeText(broken, "{ \"format\": \"ggstudio-model\", ");

    Document document;
    edit(document);
    const core::Model before(document.model());
    const int commands = document.undoStack()->count();
    QSignalSpy reset(&document, &Document::modelReset);
    QSignalSpy pathChanged(&document, &Document::filePathChanged);

    QString error;
    QVERIFY(!document.load(broken, &error));
    QVERIFY2(error.startsWith(broken + ": "), qPrintable(error));
    QVERIFY(!document.load(directory.filePath("missing.ggs.json"), &error));
    QVERIFY2(error.contains("missing.ggs.json"), qPrintable(error));
    QVERIFY(!document.load(broken, nullptr));

    QVERIFY(document.model().sameContent(before));
    QCOMPARE(document.undoStack()->count(), commands);
    QVERIFY(document.isModified());
    QVERIFY(document.filePath().isEmpty());
    QCOMPARE(reset.count(), 0);
    QCOMPARE(pathChanged.count(), 0);
    document.undoStack()->undo(); // the history still works
    QVERIFY(!document.model().step("F6")->hidden);
}

void TestDocument::failedSaveKeepsModified()
{
    QTemporaryDir directory;
    QVERIFY(directory.isValid());
    Document document;
    edit(document);
    QString error;
    const QString path = directory.filePath("no/such/folder/press.ggs.json");
    QVERIFY(!document.save(path, &error));
    QVERIFY2(error.startsWith(path), qPrintable(error));
    QVERIFY(document.isModified());
    QVERIFY(document.filePath().isEmpty());
}

void TestDocument::replaceModelClearsHistory()
{
    Document document;
    edit(document);
    core::Model other;
    QVERIFY(other.setStepHidden("D3", true));
    QSignalSpy reset(&document, &Document::modelReset);
    QSignalSpy modified(&document, &Document::modifiedChanged);
    QSignalSpy pathChanged(&document, &Document::filePathChanged);
    document.replaceModel(other, "/tmp/imported.json", core::ModelFormat::GGGenerator);
    QVERIFY(document.model().sameContent(other));
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());
    QCOMPARE(reset.count(), 1);
    QCOMPARE(modified.count(), 1);
    QCOMPARE(pathChanged.count(), 1);
    QCOMPARE(document.fileFormat(), core::ModelFormat::GGGenerator);
}

void TestDocument::newFromTemplate()
{
    Document document;
    edit(document);
    document.newFromTemplate();
    QVERIFY(document.model().sameContent(core::Model()));
    QVERIFY(!document.isModified());
    QCOMPARE(document.displayName(), QString("Untitled"));
}

void TestDocument::selection()
{
    Selection selection;
    QSignalSpy changed(&selection, &Selection::changed);
    QSignalSpy focus(&selection, &Selection::focusFieldRequested);
    selection.select(ElementRef::step("F1"));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(focus.count(), 0);
    QCOMPARE(selection.current(), ElementRef::step("F1"));

    selection.select(ElementRef::step("F1"), "comment"); // same element: only the field
    QCOMPARE(changed.count(), 1);
    QCOMPARE(focus.count(), 1);
    QCOMPARE(focus.last().at(1).toString(), QString("comment"));

    selection.select(ElementRef::transition("F1->A2"), "condition");
    QCOMPARE(changed.count(), 2);
    QCOMPARE(focus.count(), 2);
    QCOMPARE(changed.last().at(0).value<ElementRef>(), ElementRef::transition("F1->A2"));

    selection.clear();
    QVERIFY(selection.current().isNull());
    QCOMPARE(changed.count(), 3);
    selection.clear();
    QCOMPARE(changed.count(), 3);
}

QTEST_MAIN(TestDocument)
void TestDocument::packmlDiagnosticsBelongToTheirElements()
{
    // A PackML model's findings go to its mode, command and (mode, state):
    // what the chart and the docks ask the Document for.
    core::Model model = core::packml::newModel(core::packml::Edition::Y2022);
    QVERIFY(model.setCommandCondition(core::packml::Command::Hold, "NoSuchInput"));
    QVERIFY(model.setModeRequest(3, "AlsoUndeclared"));
    QVERIFY(model.setGrafcetChoice(1, core::packml::State::Starting, core::packml::GrafcetChoice::own()));
    Document document(model);
    const auto codes = [&](const ElementRef& element) {
        QStringList result;
        for (const core::Diagnostic& d : document.diagnosticsFor(element))
            result << QString::fromStdString(d.code);
        return result;
    };
    QCOMPARE(codes(ElementRef::packmlCommand(QStringLiteral("Hold"))), QStringList{QStringLiteral("GG203")});
    QVERIFY(codes(ElementRef::packmlCommand(QStringLiteral("Start"))).isEmpty());
    QCOMPARE(codes(ElementRef::packmlMode(3)), QStringList{QStringLiteral("GG203")});
    // Starting never completes: Production cannot reach Execute (PM008).
    QCOMPARE(codes(ElementRef::packmlMode(1)), QStringList{QStringLiteral("PM008")});
    QVERIFY(codes(ElementRef::packmlMode(2)).isEmpty());
    QVERIFY(codes(ElementRef::packmlState(QStringLiteral("Starting"), 1)).contains(QStringLiteral("PM010")));
    QVERIFY(codes(ElementRef::packmlState(QStringLiteral("Starting"), 0)).contains(QStringLiteral("PM010")));
    QVERIFY(codes(ElementRef::packmlState(QStringLiteral("Starting"), 2)).isEmpty());
    QVERIFY(document.hasProblems(ElementRef::packmlCommand(QStringLiteral("Hold"))));
}

#include "test_document.moc"
