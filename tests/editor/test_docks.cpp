// The five docks: they show the selection, edit only through undoable
// commands, follow undo, and talk to each other through the Selection
// (a problem's double-click focuses the field at fault).

#include "editor/app/languages.h"
#include "editor/commands/addvariablecommand.h"
#include "editor/commands/setconditioncommand.h"
#include "editor/commands/setdialectcommand.h"
#include "editor/commands/setelementshiddencommand.h"
#include "editor/commands/setinitialstepcommand.h"
#include "editor/commands/setstepcommentcommand.h"
#include "editor/commands/setstephiddencommand.h"
#include "editor/commands/setsteptypecommand.h"
#include "editor/commands/settokenscommand.h"
#include "editor/docks/conditionedit.h"
#include "editor/docks/gemma/startguide.h"
#include "editor/docks/gemma/stepdock.h"
#include "editor/docks/gemma/transitiondock.h"
#include "editor/docks/problemsdock.h"
#include "editor/docks/stpreviewdock.h"
#include "editor/docks/variablesdock.h"
#include "editor/docks/variablestablemodel.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/style/secondarytext.h"
#include "editor/style/severityicon.h"
#include "editor/text/conditionerrortext.h"
#include "editor/text/conditiontypeerrortext.h"
#include "editor/text/diagnostictext.h"
#include "editor/text/packmldiagnostictext.h"
#include "editor/text/valueproblemtext.h"

#include "core/templates/gemma/gemmacodegen.h"
#include "core/condition/conditionanalysis.h"
#include "core/condition/conditionparser.h"
#include "core/condition/symboltable.h"
#include "core/formats/modelfiles.h"
#include "core/checks/checks.h"
#include "core/templates/packml/packmlmodel.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCompleter>
#include <QHeaderView>
#include <QHelpEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTableView>
#include <QTest>
#include <QTextBlock>
#include <QToolButton>
#include <QToolTip>
#include <QTreeWidget>
#include <QUndoStack>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

using namespace editor;

namespace {

void declare(Document& document, const std::string& name, core::IecType type = core::IecType::Bool)
{
    core::Variable variable;
    variable.name = name;
    variable.type = type;
    QVERIFY(document.push(new AddVariableCommand(document, variable)));
}

template <typename Widget> Widget* child(QObject* parent, const char* name)
{
    auto* widget = parent->findChild<Widget*>(QString::fromLatin1(name));
    if (!widget)
        qWarning("no child named %s", name);
    return widget;
}

QTreeWidgetItem* problemItem(QTreeWidget* view, const QString& code, const QString& elementText)
{
    for (int i = 0; i < view->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = view->topLevelItem(i);
        if (item->text(ProblemsDock::CodeColumn) == code && item->text(ProblemsDock::ElementColumn) == elementText)
            return item;
    }
    return nullptr;
}

const QTextEdit::ExtraSelection* underlineAt(const ConditionEdit* edit, int begin, int end)
{
    static QList<QTextEdit::ExtraSelection> selections;
    selections = edit->extraSelections();
    for (const QTextEdit::ExtraSelection& selection : selections) {
        if (selection.cursor.selectionStart() == begin && selection.cursor.selectionEnd() == end)
            return &selection;
    }
    return nullptr;
}

} // namespace

class TestDocks : public QObject {
    Q_OBJECT

private slots:
    void severityIconsAreDrawnOnTransparency();
    void stepDockShowsSelectedStep();
    void stepDockTypeComboPushesUndoableCommand();
    void stepDockInitialHiddenAndComment();
    void initialStepIsNeverHidden();
    void stepDockListsTransitionsByPriority();
    void propertyDocksFollowTheirKindAndFocusFields();
    void transitionDockUnderlinesUndeclaredVariable();
    void transitionDockListsItsProblemsUnderTheFields();
    void conditionTypingIsOneUndoStep();
    void conditionEditCompletesVariableNames();
    void tokenCheckboxesShowPolarity();
    void priorityAndNegation();
    void familyTransitionHeader();
    void variablesModelRenameRewritesConditions();
    void variablesModelRefusesDuplicateName();
    void variablesKindColumnEditsTheKind();
    void variablesModelRefusesInvalidNameKeepingConditions();
    void variablesModelAcceptsStepIdsTheCodeDoesNotDeclare();
    void variablesMessageGoesAtTheNextEdit();
    void invalidDefaultIsRedWithTooltip();
    void pasteAddsVariablesInOneUndoStep();
    void pasteRejectsBadRows();
    void sortByNameIsOneUndoStep();
    void selectingRowSelectsVariable();
    void doubleClickingProblemSelectsElement();
    void problemMessagesWrapInANarrowDock();
    void nestedProblemsStandUnderTheirGemmaStep();
    void problemFiltersCountAndHide();
    void problemFocusesConditionSpan();
    void stPreviewShowsProgramAndHighlightsStep();
    void stPreviewDialectIsUndoable();
    void stPreviewRewritesOnlyWhatChanged();
    void wrappingLabelHeightFollowsTextAndFont();
    void diagnosticTextTranslatesByCode();
    void diagnosticTextWordsTheTeacherChecks();
    void diagnosticTextWordsEveryPackMLCheck();
    void secondaryTextIsReadable();
    void syntaxErrorsAreInTheUiLanguage();
    void typeAndValueErrorsAreInTheUiLanguage();
    void objectNamesForSaveState();
};

void TestDocks::stepDockShowsSelectedStep()
{
    Document document;
    Selection selection;
    StepDock dock(&document, &selection);
    selection.select(ElementRef::step("F1"));
    QCOMPARE(dock.stepId(), QString("F1"));
    QCOMPARE(child<QLabel>(&dock, "idLabel")->text(), QString("F1"));
    QCOMPARE(child<QLabel>(&dock, "nameLabel")->text(), QString("Normal production"));
    auto* type = child<QComboBox>(&dock, "typeCombo");
    QCOMPARE(type->currentData().toInt(), static_cast<int>(core::StepType::Macro));
    QCOMPARE(type->currentText(), QString("Macro-step"));

    selection.select(ElementRef::transition("A1->F4"));
    QVERIFY(dock.stepId().isEmpty()); // the placeholder page
    selection.select(ElementRef::step("F4"));
    QCOMPARE(type->currentData().toInt(), static_cast<int>(core::StepType::Enclosing));
}

void TestDocks::stepDockTypeComboPushesUndoableCommand()
{
    Document document;
    Selection selection;
    StepDock dock(&document, &selection);
    selection.select(ElementRef::step("F1"));
    auto* type = child<QComboBox>(&dock, "typeCombo");
    type->setCurrentIndex(type->findData(static_cast<int>(core::StepType::Simple)));
    QCOMPARE(document.model().step("F1")->type, core::StepType::Simple);
    QCOMPARE(document.undoStack()->count(), 1);

    document.undoStack()->undo();
    QCOMPARE(document.model().step("F1")->type, core::StepType::Macro);
    QCOMPARE(type->currentData().toInt(), static_cast<int>(core::StepType::Macro));
    document.undoStack()->redo();
    QCOMPARE(type->currentData().toInt(), static_cast<int>(core::StepType::Simple));
}

void TestDocks::stepDockInitialHiddenAndComment()
{
    Document document;
    Selection selection;
    StepDock dock(&document, &selection);
    auto* initial = child<QCheckBox>(&dock, "initialCheck");
    selection.select(ElementRef::step("A6"));
    QVERIFY(initial->isChecked());
    QVERIFY(!initial->isEnabled()); // there is always one initial step
    QVERIFY(initial->toolTip().contains("another step"));

    selection.select(ElementRef::step("A1"));
    QVERIFY(!initial->isChecked());
    initial->click();
    QVERIFY(document.model().step("A1")->initial);
    QVERIFY(!document.model().step("A6")->initial);
    QVERIFY(!initial->isEnabled());
    document.undoStack()->undo();
    QVERIFY(document.model().step("A6")->initial);
    QVERIFY(!initial->isChecked());
    QVERIFY(initial->isEnabled());

    auto* hidden = child<QCheckBox>(&dock, "hiddenCheck");
    hidden->click();
    QVERIFY(document.model().step("A1")->hidden);

    auto* comment = child<QPlainTextEdit>(&dock, "commentEdit");
    QTest::keyClicks(comment, "Idle");
    QCOMPARE(document.model().step("A1")->comment, std::string("Idle"));
    QCOMPARE(document.undoStack()->count(), 2); // the hiding, then the typing as one step
    document.undoStack()->undo();
    QCOMPARE(comment->toPlainText(), QString());
}

// The PLC starts in the initial step: no command hides it or makes a hidden
// step initial, each refusal says why, and the Step dock's boxes say it
// before. A file that hides it opens as it is, GG001 saying so, and the box
// shows it again.
void TestDocks::initialStepIsNeverHidden()
{
    Document document;
    QCOMPARE(document.model().initialStep().id, std::string("A6"));
    QSignalSpy refused(&document, &Document::editFailed);
    QVERIFY(!document.push(new SetStepHiddenCommand(document, "A6", true)));
    QVERIFY(!document.push(new SetElementsHiddenCommand(
        document, {ElementRef::step("F4"), ElementRef::step("A6"), ElementRef::transition("A6->A1")}, true)));
    QCOMPARE(refused.size(), 2);
    for (const QList<QVariant>& signal : refused)
        QVERIFY2(signal.front().toString().contains("A6 is the initial step"), qPrintable(signal.front().toString()));
    QVERIFY(!document.model().step("A6")->hidden);
    QVERIFY(!document.model().step("F4")->hidden); // all or nothing
    QVERIFY(!document.model().transition("A6->A1")->hidden);
    QCOMPARE(document.undoStack()->count(), 0);
    // A hidden step is not made initial either.
    QVERIFY(document.push(new SetStepHiddenCommand(document, "A1", true)));
    QVERIFY(!document.push(new SetInitialStepCommand(document, "A1")));
    QVERIFY(refused.back().front().toString().contains("A1 is hidden"));
    QVERIFY(document.model().step("A6")->initial);

    Selection selection;
    StepDock dock(&document, &selection);
    auto* initial = child<QCheckBox>(&dock, "initialCheck");
    auto* hidden = child<QCheckBox>(&dock, "hiddenCheck");
    selection.select(ElementRef::step("A6"));
    QVERIFY(!hidden->isEnabled());
    QVERIFY(hidden->toolTip().contains("A6 is the initial step"));
    selection.select(ElementRef::step("A1"));
    QVERIFY(hidden->isEnabled());
    QVERIFY(!initial->isEnabled());
    QVERIFY(initial->toolTip().contains("A1 is hidden"));

    // A file that hides its initial step opens as it is; GG001 says so, and
    // the Hidden box shows the step.
    core::Model hiding;
    QVERIFY(hiding.setStepHidden("A6", true));
    document.replaceModel(hiding, QString(), core::ModelFormat::Native);
    QVERIFY(document.model().step("A6")->hidden);
    QVERIFY(std::any_of(document.diagnostics().begin(), document.diagnostics().end(),
                        [](const core::Diagnostic& d) { return d.code == "GG001"; }));
    selection.select(ElementRef::step("A6"));
    QVERIFY(hidden->isChecked());
    QVERIFY(hidden->isEnabled());
    hidden->click();
    QVERIFY(!document.model().step("A6")->hidden);
}

void TestDocks::stepDockListsTransitionsByPriority()
{
    Document document;
    Selection selection;
    StepDock dock(&document, &selection);
    selection.select(ElementRef::step("A1"));
    auto* outgoing = child<QTreeWidget>(&dock, "outgoingList");
    QCOMPARE(outgoing->topLevelItemCount(), 4);
    QCOMPARE(outgoing->topLevelItem(0)->text(0), QString("1: → F4"));
    QCOMPARE(outgoing->topLevelItem(1)->text(0), QString("2: → F2"));
    QCOMPARE(outgoing->topLevelItem(3)->text(0), QString("4: → F5"));

    // Hiding F2 makes A1->F2 ineffective: no priority, greyed; the rest renumber.
    QVERIFY(document.push(new SetStepHiddenCommand(document, "F2", true)));
    QCOMPARE(outgoing->topLevelItem(1)->text(0), QString("–: → F2"));
    QVERIFY(outgoing->topLevelItem(1)->font(0).italic());
    QCOMPARE(outgoing->topLevelItem(2)->text(0), QString("2: → F1"));

    // F states list the family transition first.
    selection.select(ElementRef::step("F1"));
    QCOMPARE(outgoing->topLevelItem(0)->data(0, Qt::UserRole).toString(), QString("F->D1"));
    auto* incoming = child<QTreeWidget>(&dock, "incomingList");
    QCOMPARE(incoming->topLevelItemCount(), static_cast<int>(document.model().incoming("F1").size()));
    // F1 -> D1 is negated in the template: the list says so.
    for (int i = 0; i < outgoing->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = outgoing->topLevelItem(i);
        const QString id = item->data(0, Qt::UserRole).toString();
        QCOMPARE(item->text(0).endsWith(QStringLiteral(" (negated)")),
                 document.model().transition(id.toStdString())->negated);
        if (id == QLatin1String("F1->D1"))
            QCOMPARE(item->text(0), QStringLiteral("%1: \u2192 D1 (negated)").arg(document.model().priority("F1->D1")));
    }

    // A link selects its transition.
    outgoing->setCurrentItem(outgoing->topLevelItem(1));
    emit outgoing->itemClicked(outgoing->topLevelItem(1), 0);
    QCOMPARE(selection.current(), ElementRef::transition("F1->D1"));
}

// What the Step and Transition docks share (PropertyDock): each shows its
// form for its own kind of element only, and a request for a field of that
// element reveals the dock and focuses the field.
void TestDocks::propertyDocksFollowTheirKindAndFocusFields()
{
    Document document;
    Selection selection;
    StepDock steps(&document, &selection);
    TransitionDock transitions(&document, &selection);
    auto* stepPages = qobject_cast<QStackedWidget*>(steps.widget());
    auto* transitionPages = qobject_cast<QStackedWidget*>(transitions.widget());
    QVERIFY(stepPages && transitionPages);
    QLabel* stepPlaceholder = child<QLabel>(&steps, "placeholder");
    QLabel* transitionPlaceholder = child<QLabel>(&transitions, "placeholder");
    // Nothing selected: the Step dock shows the start guide.
    QVERIFY(stepPages->currentWidget()->findChild<StartGuide*>());
    QCOMPARE(transitionPages->currentWidget(), transitionPlaceholder);
    QVERIFY(steps.isHidden() && transitions.isHidden());

    selection.select(ElementRef::step("F1"), "comment");
    QVERIFY(stepPages->currentWidget() != stepPlaceholder);
    QCOMPARE(transitionPages->currentWidget(), transitionPlaceholder);
    QVERIFY(!steps.isHidden());
    QVERIFY(transitions.isHidden());
    QCOMPARE(steps.focusWidget(), child<QPlainTextEdit>(&steps, "commentEdit"));

    selection.select(ElementRef::transition("A1->F4"), "negated");
    QCOMPARE(stepPages->currentWidget(), stepPlaceholder);
    QVERIFY(steps.stepId().isEmpty());
    QVERIFY(transitionPages->currentWidget() != transitionPlaceholder);
    QVERIFY(!transitions.isHidden());
    QCOMPARE(transitions.focusWidget(), child<QCheckBox>(&transitions, "negatedCheck"));

    // An element the model does not have shows the placeholder.
    selection.select(ElementRef::transition("A1->Nowhere"), "negated");
    QVERIFY(transitions.transitionId().isEmpty());
    QCOMPARE(transitionPages->currentWidget(), transitionPlaceholder);
}

namespace {

// The texts of the visible rows of a DiagnosticList.
QStringList visibleProblemRows(const QWidget* list)
{
    QStringList rows;
    for (const QLabel* label : list->findChildren<QLabel*>()) {
        if (label->wordWrap() && label->isVisibleTo(list))
            rows << label->text();
    }
    return rows;
}

} // namespace

void TestDocks::transitionDockListsItsProblemsUnderTheFields()
{
    Document document;
    Selection selection;
    declare(document, "Start");
    TransitionDock dock(&document, &selection);
    dock.resize(340, 600);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    selection.select(ElementRef::transition("A1->F4"));
    auto* list = child<QWidget>(&dock, "problemList");

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Foo AND Bar")));
    QTRY_COMPARE(visibleProblemRows(list).size(), 2);
    QVERIFY(list->isVisible());
    QStringList rows = visibleProblemRows(list);
    QVERIFY(rows[0].contains("'Foo'"));
    QVERIFY(rows[1].contains("'Bar'"));

    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Start")));
    QTRY_VERIFY2(!list->isVisible(), qPrintable(visibleProblemRows(list).join('\n')));

    // Problems that come and go as one types: the list follows.
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Baz")));
    QTRY_COMPARE(visibleProblemRows(list).size(), 1);
    QVERIFY(list->isVisible());
    QVERIFY(visibleProblemRows(list).constFirst().contains("'Baz'"));
}

void TestDocks::transitionDockUnderlinesUndeclaredVariable()
{
    Document document;
    Selection selection;
    declare(document, "Start");
    TransitionDock transitions(&document, &selection);
    ProblemsDock problems(&document, &selection);
    selection.select(ElementRef::transition("A1->F4"));
    QCOMPARE(transitions.transitionId(), QString("A1->F4"));

    auto* edit = child<ConditionEdit>(&transitions, "conditionEdit");
    QTest::keyClicks(edit, "Start AND Foo");
    QCOMPARE(document.model().transition("A1->F4")->condition, std::string("Start AND Foo"));

    QTreeWidgetItem* item = problemItem(problems.view(), "GG203", "A1 → F4");
    QVERIFY(item);
    QVERIFY(item->text(ProblemsDock::MessageColumn).contains("'Foo' is not a declared variable"));

    const QTextEdit::ExtraSelection* underline = underlineAt(edit, 10, 13);
    QVERIFY(underline);
    QCOMPARE(underline->format.underlineStyle(), QTextCharFormat::SpellCheckUnderline);
    QCOMPARE(underline->format.underlineColor(), QColor(Qt::red));
    QCOMPARE(edit->extraSelections().size(), 1);
    QCOMPARE(edit->problems().front().message, item->text(ProblemsDock::MessageColumn));

    // Hovering the underlined name shows the message.
    transitions.resize(340, 500);
    transitions.show();
    QVERIFY(QTest::qWaitForWindowExposed(&transitions));
    QTextCursor cursor(edit->document());
    cursor.setPosition(11);
    const QPoint inside = edit->cursorRect(cursor).center() + QPoint(2, 0);
    QHelpEvent hover(QEvent::ToolTip, inside, edit->viewport()->mapToGlobal(inside));
    QApplication::sendEvent(edit->viewport(), &hover);
    QCOMPARE(QToolTip::text(), item->text(ProblemsDock::MessageColumn));

    // Declaring the variable removes the problem and the underline.
    declare(document, "Foo");
    QVERIFY(!problemItem(problems.view(), "GG203", "A1 → F4"));
    QVERIFY(edit->extraSelections().isEmpty());
}

void TestDocks::conditionTypingIsOneUndoStep()
{
    Document document;
    Selection selection;
    TransitionDock dock(&document, &selection);
    selection.select(ElementRef::transition("F1->A2"));
    auto* edit = child<ConditionEdit>(&dock, "conditionEdit");
    QTest::keyClicks(edit, "TRUE");
    QTest::keyClick(edit, Qt::Key_Return); // one paragraph: ignored
    QCOMPARE(edit->text(), QString("TRUE"));
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string());
    QCOMPARE(edit->text(), QString());

    // Spans count UTF-8 bytes; the editor counts UTF-16 units.
    QCOMPARE(ConditionEdit::positionOfByte(QString::fromUtf8("é AND x"), 2), 1);
    QCOMPARE(ConditionEdit::positionOfByte(QString::fromUtf8("a"), 10), 1);
}

void TestDocks::conditionEditCompletesVariableNames()
{
    Document document;
    Selection selection;
    declare(document, "StartButton");
    declare(document, "Stop");
    TransitionDock dock(&document, &selection);
    dock.show();
    selection.select(ElementRef::transition("A1->F4"));
    auto* edit = child<ConditionEdit>(&dock, "conditionEdit");
    QCOMPARE(edit->completer()->caseSensitivity(), Qt::CaseInsensitive);
    QTest::keyClicks(edit, "NOT sta");
    QCOMPARE(edit->completer()->completionPrefix(), QString("sta"));
    QCOMPARE(edit->completer()->currentCompletion(), QString("StartButton"));
    QVERIFY(edit->completer()->popup()->isVisible());
    emit edit->completer()->activated(QString("StartButton"));
    QCOMPARE(edit->text(), QString("NOT StartButton"));
    QCOMPARE(document.model().transition("A1->F4")->condition, std::string("NOT StartButton"));
}

void TestDocks::tokenCheckboxesShowPolarity()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    declare(document, "Go");
    declare(document, "Speed", core::IecType::Int);
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "NOT Stop AND go AND Speed > 3")));
    document.undoStack()->clear();
    TransitionDock dock(&document, &selection);
    selection.select(ElementRef::transition("F1->A2"));

    auto* stop = child<QCheckBox>(&dock, "tokenCheck_Stop");
    auto* go = child<QCheckBox>(&dock, "tokenCheck_Go"); // the declared spelling
    QVERIFY(stop && go);
    QCOMPARE(stop->text(), QString("Token on Stop (NC)"));
    QCOMPARE(go->text(), QString("Token on Go (NO)"));
    QVERIFY(!dock.findChild<QCheckBox*>("tokenCheck_Speed")); // not BOOL
    QVERIFY(stop->isEnabled());
    QVERIFY(stop->toolTip().contains("Stop_F1_3_MEM"));

    stop->click();
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string> { "Stop" });
    QVERIFY(stop->isChecked());
    document.undoStack()->undo();
    QVERIFY(document.model().transition("F1->A2")->tokens.empty());
    QVERIFY(!stop->isChecked());

    // Out of a simple step tokens do not apply: the boxes are disabled.
    selection.select(ElementRef::transition("A1->F4"));
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Go")));
    auto* simpleGo = child<QCheckBox>(&dock, "tokenCheck_Go");
    QVERIFY(simpleGo);
    QVERIFY(!simpleGo->isEnabled());
    QVERIFY(child<QLabel>(&dock, "tokenHint")->text().contains("simple step"));
}

void TestDocks::priorityAndNegation()
{
    Document document;
    Selection selection;
    TransitionDock dock(&document, &selection);
    selection.select(ElementRef::transition("A1->F5"));
    auto* priority = child<QSpinBox>(&dock, "prioritySpin");
    QCOMPARE(priority->value(), 4);
    QCOMPARE(priority->maximum(), 4);
    priority->setValue(1);
    QCOMPARE(document.model().priority("A1->F5"), 1);
    QCOMPARE(document.model().priority("A1->F4"), 2);
    document.undoStack()->undo();
    QCOMPARE(priority->value(), 4);

    auto* negated = child<QCheckBox>(&dock, "negatedCheck");
    auto* hint = child<QLabel>(&dock, "negatedHint");
    QVERIFY(hint->text().contains("no effect")); // A1 is a simple step
    selection.select(ElementRef::transition("F1->A2"));
    QVERIFY(hint->text().contains("Waits"));
    negated->click();
    QVERIFY(document.model().transition("F1->A2")->negated);
    QVERIFY(hint->text().contains("without waiting"));

    auto* hidden = child<QCheckBox>(&dock, "hiddenCheck");
    hidden->click();
    QVERIFY(document.model().transition("F1->A2")->hidden);
    QVERIFY(!priority->isEnabled()); // no priority when not effective
    QVERIFY(!priority->toolTip().isEmpty());
}

void TestDocks::familyTransitionHeader()
{
    Document document;
    Selection selection;
    TransitionDock dock(&document, &selection);
    selection.select(ElementRef::transition("F->D1"));
    auto* title = child<QLabel>(&dock, "titleLabel");
    QVERIFY(title->text().startsWith("F (family) → "));
    QVERIFY(title->text().contains(">D1</a>"));
    emit title->linkActivated("D1");
    QCOMPARE(selection.current(), ElementRef::step("D1"));
}

void TestDocks::variablesModelRenameRewritesConditions()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "NOT Stop")));
    QVERIFY(document.push(new SetTokensCommand(document, "F1->A2", { "Stop" })));
    document.undoStack()->clear();
    VariablesDock dock(&document, &selection);
    VariablesTableModel* model = dock.tableModel();
    QCOMPARE(model->rowCount(), 1);
    const QModelIndex name = model->index(0, VariablesTableModel::NameColumn);
    QCOMPARE(name.data().toString(), QString("Stop"));

    QVERIFY(model->setData(name, "Halt"));
    QCOMPARE(document.model().variables().front().name, std::string("Halt"));
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("NOT Halt"));
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string> { "Halt" });
    QCOMPARE(name.data().toString(), QString("Halt"));
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("NOT Stop"));
    QCOMPARE(name.data().toString(), QString("Stop"));

    // The other columns push their own commands.
    QVERIFY(model->setData(model->index(0, VariablesTableModel::TypeColumn), "INT"));
    QCOMPARE(document.model().variables().front().type, core::IecType::Int);
    QVERIFY(!model->setData(model->index(0, VariablesTableModel::TypeColumn), "STRING"));
    QVERIFY(model->setData(model->index(0, VariablesTableModel::DefaultColumn), " 5 "));
    QCOMPARE(document.model().variables().front().defaultValue, std::string("5"));
    QVERIFY(model->setData(model->index(0, VariablesTableModel::CommentColumn), "Stop button"));
    QCOMPARE(document.model().variables().front().comment, std::string("Stop button"));
}

void TestDocks::variablesKindColumnEditsTheKind()
{
    Document document;
    Selection selection;
    declare(document, "Valve");
    declare(document, "Start");
    document.undoStack()->clear();
    VariablesDock dock(&document, &selection);
    QTableView* view = dock.view();
    QAbstractItemModel* shown = view->model();
    QCOMPARE(shown->headerData(VariablesTableModel::KindColumn, Qt::Horizontal).toString(), QString("Kind"));
    QCOMPARE(shown->headerData(VariablesTableModel::TypeColumn + 1, Qt::Horizontal).toString(), QString("Kind"));
    const QModelIndex valveKind = shown->index(0, VariablesTableModel::KindColumn);
    QCOMPARE(valveKind.data().toString(), QString("Input"));
    // Narrow, for the dock column beside the chart.
    QVERIFY(view->horizontalHeader()->sectionSize(VariablesTableModel::KindColumn) <= 80);

    // The delegate's combo box commits the choice at once, as one command.
    view->setCurrentIndex(valveKind);
    view->edit(valveKind);
    auto* combo = view->findChild<QComboBox*>("kindCombo");
    QVERIFY(combo);
    QCOMPARE(combo->count(), 3);
    QCOMPARE(combo->currentText(), QString("Input"));
    QCOMPARE(combo->itemText(1), QString("Output"));
    combo->setCurrentIndex(combo->findData(QString("output")));
    emit combo->activated(combo->currentIndex());
    QCOMPARE(document.model().variable("Valve")->kind, core::VariableKind::Output);
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QString("Set kind of Valve to output"));
    QCOMPARE(valveKind.data().toString(), QString("Output"));
    document.undoStack()->undo();
    QCOMPARE(document.model().variable("Valve")->kind, core::VariableKind::Input);
    QCOMPARE(valveKind.data().toString(), QString("Input"));
    document.undoStack()->redo();

    // Typed names: the file's and the shown one; anything else is refused.
    VariablesTableModel* model = dock.tableModel();
    QVERIFY(model->setData(model->index(1, VariablesTableModel::KindColumn), "internal"));
    QCOMPARE(document.model().variable("Start")->kind, core::VariableKind::Internal);
    QVERIFY(model->setData(model->index(1, VariablesTableModel::KindColumn), "Input"));
    QCOMPARE(document.model().variable("Start")->kind, core::VariableKind::Input);
    QVERIFY(!model->setData(model->index(1, VariablesTableModel::KindColumn), "sensor"));
    QCOMPARE(document.undoStack()->count(), 3);

    // The filter matches the shown kind.
    auto* filter = child<QLineEdit>(&dock, "filterEdit");
    filter->setText("outp");
    QCOMPARE(shown->rowCount(), 1);
    QCOMPARE(shown->index(0, VariablesTableModel::NameColumn).data().toString(), QString("Valve"));
    filter->clear();

    // Copy and paste carry the kind; rows without one are inputs.
    view->selectAll();
    QCOMPARE(dock.copiedText(), QString("Name\tType\tDefault\tComment\tKind\nValve\tBOOL\t\t\toutput\n"
                                        "Start\tBOOL\t\t\tinput\n"));
    std::vector<core::Variable> rows;
    QString error;
    QVERIFY(VariablesTableModel::parseRows("A\tBOOL\t\t\tOutput\nB\tINT\t\t\tinternal\nC\tBOOL", &rows, &error));
    QCOMPARE(rows.size(), std::size_t(3));
    QCOMPARE(rows[0].kind, core::VariableKind::Output);
    QCOMPARE(rows[1].kind, core::VariableKind::Internal);
    QCOMPARE(rows[2].kind, core::VariableKind::Input);
    QVERIFY(!VariablesTableModel::parseRows("Name\tType\tDefault\tComment\tKind\nA\tBOOL\t\t\tsensor", &rows, &error));
    QVERIFY2(error.startsWith("Line 2: 'sensor' is not a kind"), qPrintable(error));

    // In the UI language.
    Translators translators;
    QVERIFY(translators.setLanguage("fr"));
    QCOMPARE(valveKind.data().toString(), QString("Sortie"));
    QCOMPARE(shown->headerData(VariablesTableModel::KindColumn, Qt::Horizontal).toString(), QString("Nature"));
    QVERIFY(model->setData(model->index(1, VariablesTableModel::KindColumn), QString("Interne")));
    QCOMPARE(document.model().variable("Start")->kind, core::VariableKind::Internal);
    QVERIFY(translators.setLanguage("en"));
}

void TestDocks::variablesModelRefusesDuplicateName()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    declare(document, "Go");
    document.undoStack()->clear();
    VariablesDock dock(&document, &selection);
    VariablesTableModel* model = dock.tableModel();
    QSignalSpy refused(model, &VariablesTableModel::editRefused);
    QVERIFY(!model->setData(model->index(1, VariablesTableModel::NameColumn), "STOP"));
    QCOMPARE(refused.count(), 1);
    const QString message = refused.front().at(1).toString();
    QVERIFY2(message.contains("already exists"), qPrintable(message));
    QCOMPARE(child<QLabel>(&dock, "messageLabel")->text(), message);
    QCOMPARE(document.model().variables()[1].name, std::string("Go"));
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestDocks::variablesModelRefusesInvalidNameKeepingConditions()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    declare(document, "Start");
    QVERIFY(document.push(new SetConditionCommand(document, "F1->A2", "Start AND NOT Stop")));
    QVERIFY(document.push(new SetTokensCommand(document, "F1->A2", { "Stop" })));
    document.undoStack()->clear();
    VariablesDock dock(&document, &selection);
    VariablesTableModel* model = dock.tableModel();
    const QModelIndex name = model->index(0, VariablesTableModel::NameColumn);
    QSignalSpy refused(model, &VariablesTableModel::editRefused);

    // A blank, a keyword, a type name, a leading digit, a generator name, '__'.
    for (const QString& invalid : { QString("Stop 2"), QString("AND"), QString("int"), QString("2Stop"),
             QString("GEMMA"), QString("Stop__2"), QString("  ") }) {
        refused.clear();
        QVERIFY2(!model->setData(name, invalid), qPrintable(invalid));
        QCOMPARE(refused.count(), 1);
        const QString message = refused.front().at(1).toString();
        const QString expectedReason = invalid.trimmed().isEmpty() ? QString("needs a name")
                                                                   : identifierProblemText(invalid);
        QVERIFY2(message.contains(expectedReason), qPrintable(message));
        QCOMPARE(child<QLabel>(&dock, "messageLabel")->text(), message);
        QCOMPARE(document.model().variables().front().name, std::string("Stop"));
        QCOMPARE(document.model().transition("F1->A2")->condition, std::string("Start AND NOT Stop"));
        QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string> { "Stop" });
        QCOMPARE(document.undoStack()->count(), 0);
    }
    QVERIFY(identifierProblemText("Stop 2").contains("Stop 2"));

    // The conditions still name the variable: a valid name follows it there.
    QVERIFY(model->setData(name, "Stop2"));
    QCOMPARE(document.model().transition("F1->A2")->condition, std::string("Start AND NOT Stop2"));
    QCOMPARE(document.model().transition("F1->A2")->tokens, std::vector<std::string> { "Stop2" });
}

// a1 is the usual name of a limit switch: only the instances the generated
// code declares (visible macro-steps and enclosing steps) clash, and the
// checks then say so on the variable and on the step.
void TestDocks::variablesModelAcceptsStepIdsTheCodeDoesNotDeclare()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    VariablesDock dock(&document, &selection);
    VariablesTableModel* model = dock.tableModel();
    const auto codes = [&](const QString& code) {
        QStringList elements;
        for (const core::Diagnostic& d : document.diagnostics()) {
            if (d.code == code.toStdString())
                elements << QString::fromStdString(d.element);
        }
        return elements;
    };

    QVERIFY(model->setData(model->index(0, VariablesTableModel::NameColumn), "a1"));
    QCOMPARE(document.model().variables().front().name, std::string("a1"));
    QVERIFY(codes("GG306").isEmpty());

    QVERIFY(document.push(new SetStepTypeCommand(document, "A1", core::StepType::Macro)));
    QCOMPARE(codes("GG306"), QStringList { "a1" });
    QCOMPARE(codes("GG307"), QStringList { "A1" });
    for (const core::Diagnostic& d : document.diagnostics()) {
        if (d.code == "GG306")
            QCOMPARE(diagnosticText(d),
                     QString("Variable 'a1' has the name of the instance of macro-step A1 in the generated code: "
                             "rename the variable (for example to 'a1_Sensor')."));
        if (d.code == "GG307")
            QCOMPARE(diagnosticText(d),
                     QString("Macro-step A1 declares its instance A1 in the generated code, and variable 'a1' has "
                             "that name: rename the variable (for example to 'a1_Sensor'), or make A1 a simple "
                             "step."));
    }
    document.undoStack()->undo();
    QVERIFY(codes("GG307").isEmpty());
}

void TestDocks::variablesMessageGoesAtTheNextEdit()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    declare(document, "Start");
    VariablesDock dock(&document, &selection);
    VariablesTableModel* model = dock.tableModel();
    auto* messageRow = child<QWidget>(&dock, "messageRow");
    QVERIFY(messageRow->isHidden());

    QVERIFY(!model->setData(model->index(0, VariablesTableModel::NameColumn), "Start"));
    QVERIFY(child<QLabel>(&dock, "messageLabel")->text().contains("already exists"));
    QVERIFY(!messageRow->isHidden());
    // Another refusal keeps a message up.
    QVERIFY(!model->setData(model->index(0, VariablesTableModel::NameColumn), "Stop 2"));
    QVERIFY(!messageRow->isHidden());

    QVERIFY(model->setData(model->index(0, VariablesTableModel::NameColumn), "Halt"));
    QVERIFY(messageRow->isHidden());

    // Any edit that goes through, in another column too.
    QVERIFY(!model->setData(model->index(1, VariablesTableModel::NameColumn), "halt"));
    QVERIFY(!messageRow->isHidden());
    QVERIFY(model->setData(model->index(1, VariablesTableModel::CommentColumn), "Start button"));
    QVERIFY(messageRow->isHidden());
}

void TestDocks::invalidDefaultIsRedWithTooltip()
{
    Document document;
    Selection selection;
    declare(document, "Speed", core::IecType::Sint);
    declare(document, "AND");
    VariablesDock dock(&document, &selection);
    VariablesTableModel* model = dock.tableModel();
    const QModelIndex value = model->index(0, VariablesTableModel::DefaultColumn);
    QVERIFY(!value.data(Qt::BackgroundRole).isValid());
    QCOMPARE(value.data().toString(), QString("0")); // the implicit default, greyed
    QVERIFY(model->setData(value, "300"));
    QVERIFY(value.data(Qt::BackgroundRole).value<QColor>().isValid());
    QVERIFY(value.data(Qt::ToolTipRole).toString().contains("out of range"));

    const QModelIndex keyword = model->index(1, VariablesTableModel::NameColumn);
    QVERIFY(keyword.data(Qt::BackgroundRole).value<QColor>().isValid());
    QVERIFY(keyword.data(Qt::ToolTipRole).toString().contains("keyword"));
    QVERIFY(!model->index(0, VariablesTableModel::NameColumn).data(Qt::BackgroundRole).isValid());
}

void TestDocks::pasteAddsVariablesInOneUndoStep()
{
    Document document;
    Selection selection;
    VariablesDock dock(&document, &selection);
    QVERIFY(dock.pasteVariables("A\tBOOL\t\tcomment\nB\tINT\t5\t"));
    const std::vector<core::Variable>& variables = document.model().variables();
    QCOMPARE(variables.size(), std::size_t(2));
    QCOMPARE(variables[0].name, std::string("A"));
    QCOMPARE(variables[0].type, core::IecType::Bool);
    QCOMPARE(variables[0].comment, std::string("comment"));
    QCOMPARE(variables[1].name, std::string("B"));
    QCOMPARE(variables[1].type, core::IecType::Int);
    QCOMPARE(variables[1].defaultValue, std::string("5"));
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(dock.tableModel()->rowCount(), 2);
    QCOMPARE(selection.current(), ElementRef::variable("A"));

    // A header row is skipped; pasting after the current row; a taken name gets a suffix.
    QVERIFY(dock.pasteVariables("Name\tType\tDefault\tComment\r\nA\tREAL\t1.5\t\r\n"));
    QCOMPARE(variables.size(), std::size_t(3));
    QCOMPARE(variables[1].name, std::string("A_2"));
    QCOMPARE(variables[1].type, core::IecType::Real);
    QCOMPARE(document.undoStack()->count(), 2);

    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(document.model().variables().empty());
    QCOMPARE(dock.tableModel()->rowCount(), 0);

    // Copy gives the same format back.
    QVERIFY(dock.pasteVariables("A\tBOOL\t\tcomment\n"));
    dock.view()->selectAll();
    QCOMPARE(dock.copiedText(), QString("Name\tType\tDefault\tComment\tKind\nA\tBOOL\t\tcomment\tinput\n"));
}

void TestDocks::pasteRejectsBadRows()
{
    std::vector<core::Variable> variables;
    QString error;
    QVERIFY(!VariablesTableModel::parseRows("A\tBOOL\nB\tSTRING\t\t", &variables, &error));
    QVERIFY2(error.startsWith("Line 2: 'STRING' is not a supported type"), qPrintable(error));
    QVERIFY(!VariablesTableModel::parseRows("\tINT\t5", &variables, &error));
    QVERIFY(error.startsWith("Line 1: the name is empty"));
    QVERIFY(!VariablesTableModel::parseRows("Name\tType\n\n", &variables, &error));
    QVERIFY(VariablesTableModel::parseRows("Go\n\nStop\tbool\tTRUE\tthe stop\textra", &variables, &error));
    QCOMPARE(variables.size(), std::size_t(2));
    QCOMPARE(variables[0].type, core::IecType::Bool);
    QCOMPARE(variables[1].comment, std::string("the stop"));

    Document document;
    Selection selection;
    VariablesDock dock(&document, &selection);
    QVERIFY(!dock.pasteVariables("X\tFOO"));
    QVERIFY(child<QLabel>(&dock, "messageLabel")->text().contains("FOO"));
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestDocks::sortByNameIsOneUndoStep()
{
    Document document;
    Selection selection;
    for (const char* name : { "Stop", "alarm", "Go", "Beta" })
        declare(document, name);
    document.undoStack()->clear();
    VariablesDock dock(&document, &selection);
    dock.sortByName();
    QStringList names;
    for (int row = 0; row < dock.tableModel()->rowCount(); ++row)
        names << dock.tableModel()->variableName(row);
    QCOMPARE(names, QStringList({ "alarm", "Beta", "Go", "Stop" }));
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QCOMPARE(dock.tableModel()->variableName(0), QString("Stop"));

    selection.select(ElementRef::variable("Go"));
    dock.moveCurrent(-1);
    QCOMPARE(dock.tableModel()->variableName(1), QString("Go"));
    dock.removeSelected();
    QCOMPARE(document.model().variables().size(), std::size_t(3));
    QVERIFY(!document.model().variable("Go"));
    dock.addVariable();
    QVERIFY(document.model().variable("Variable1"));
    QCOMPARE(selection.current(), ElementRef::variable("Variable1"));
}

void TestDocks::selectingRowSelectsVariable()
{
    Document document;
    Selection selection;
    declare(document, "Stop");
    declare(document, "Go");
    VariablesDock dock(&document, &selection);
    QTableView* view = dock.view();
    view->setCurrentIndex(view->model()->index(1, 0));
    QCOMPARE(selection.current(), ElementRef::variable("Go"));
    selection.select(ElementRef::variable("Stop"), "default");
    QCOMPARE(view->currentIndex().row(), 0);
    QCOMPARE(view->currentIndex().column(), int(VariablesTableModel::DefaultColumn));
}

void TestDocks::doubleClickingProblemSelectsElement()
{
    Document document;
    Selection selection;
    ProblemsDock dock(&document, &selection);
    dock.resize(800, 400);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    QSignalSpy focus(&selection, &Selection::focusFieldRequested);

    QTreeWidget* view = dock.view();
    QTreeWidgetItem* item = problemItem(view, "GG202", "A1 → F4");
    QVERIFY(item);
    view->scrollToItem(item);
    const QRect rect = view->visualItemRect(item);
    // A widget double-click in QTest is the second click only.
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, rect.center());
    QCOMPARE(selection.current(), ElementRef()); // a single click only selects the row
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, rect.center());
    QCOMPARE(selection.current(), ElementRef::transition("A1->F4"));
    QCOMPARE(focus.count(), 1);
    QCOMPARE(focus.front().at(1).toString(), QString("condition"));
}

// In the narrow dock column a message wraps over the lines it needs, and
// the row grows with it; widened, the row shrinks back to one line.
void TestDocks::problemMessagesWrapInANarrowDock()
{
    Document document;
    Selection selection;
    ProblemsDock dock(&document, &selection);
    dock.resize(340, 400);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    QTreeWidget* view = dock.view();
    QTreeWidgetItem* item = problemItem(view, "GG202", "A1 → F4");
    QVERIFY(item);
    const int line = view->fontMetrics().height();
    const QString message = item->text(ProblemsDock::MessageColumn);
    QVERIFY(view->fontMetrics().horizontalAdvance(message) > 2 * view->header()->sectionSize(ProblemsDock::MessageColumn));
    QTRY_VERIFY(view->visualItemRect(item).height() >= 3 * line);
    dock.resize(3000, 400);
    QTRY_VERIFY(view->visualItemRect(item).height() < 2 * line);
}

// The problems of a nested GRAFCET's steps and transitions are listed under
// one row for that GRAFCET, per GEMMA step; the filters and the selection
// reach them there, and a closed group stays closed through a refresh.
void TestDocks::nestedProblemsStandUnderTheirGemmaStep()
{
    const core::LoadedModel faulty =
        core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell-faulty.ggstudio.json");
    QVERIFY2(faulty.ok(), faulty.error.toString().c_str());
    Document document;
    document.replaceModel(*faulty.model, QString(), core::ModelFormat::Native);
    Selection selection;
    ProblemsDock dock(&document, &selection);
    QTreeWidget* view = dock.view();

    int nestedInF1 = 0;
    for (const core::Diagnostic& diagnostic : document.diagnostics()) {
        const bool nested = diagnostic.target == core::Diagnostic::Target::GrafcetStep
                         || diagnostic.target == core::Diagnostic::Target::GrafcetTransition;
        nestedInF1 += nested && diagnostic.element == "F1" ? 1 : 0;
    }
    QVERIFY(nestedInF1 >= 2);
    QTreeWidgetItem* group = problemItem(view, QString(), QStringLiteral("F1 GRAFCET"));
    QVERIFY(group);
    QCOMPARE(group->childCount(), nestedInF1);
    QVERIFY(group->isExpanded());
    QCOMPARE(group->text(ProblemsDock::MessageColumn), QStringLiteral("Nested GRAFCET of F1: %1 problems").arg(nestedInF1));
    for (int c = 0; c < group->childCount(); ++c)
        QVERIFY2(group->child(c)->text(ProblemsDock::ElementColumn).startsWith(QStringLiteral("F1 ")),
                 qPrintable(group->child(c)->text(ProblemsDock::ElementColumn)));
    // A GEMMA-level problem stays at the top level.
    QVERIFY(problemItem(view, QStringLiteral("GG101"), QStringLiteral("A7")));
    QVERIFY(!problemItem(view, QStringLiteral("GG101"), QStringLiteral("A7"))->parent());

    // Activating a nested problem selects that step or transition of the GRAFCET ("F1 step 7", "F1 T2").
    dock.activate(group->child(0));
    QVERIFY(selection.current().isNested());
    QCOMPARE(selection.current().id, QStringLiteral("F1"));
    const QString nestedLabel = group->child(0)->text(ProblemsDock::ElementColumn);
    QCOMPARE(nestedLabel, selection.current().kind == ElementRef::Kind::GrafcetStep
                              ? QStringLiteral("F1 step %1").arg(selection.current().number)
                              : QStringLiteral("F1 T%1").arg(selection.current().number));

    // F1's nested problems are errors: hiding the errors hides them and the group.
    child<QToolButton>(&dock, "errorsButton")->click();
    bool anyErrorShown = false;
    for (int c = 0; c < group->childCount(); ++c)
        anyErrorShown = anyErrorShown || !group->child(c)->isHidden();
    QVERIFY(!anyErrorShown);
    QVERIFY(group->isHidden());
    child<QToolButton>(&dock, "errorsButton")->click();
    QVERIFY(!group->isHidden());

    // Closed by the user, the group stays closed when the list is rebuilt.
    group->setExpanded(false);
    QVERIFY(document.push(new SetStepCommentCommand(document, QStringLiteral("A1"), QStringLiteral("Home"))));
    group = problemItem(view, QString(), QStringLiteral("F1 GRAFCET"));
    QVERIFY(group);
    QVERIFY(!group->isExpanded());
}

void TestDocks::problemFiltersCountAndHide()
{
    Document document;
    Selection selection;
    ProblemsDock dock(&document, &selection);
    int errors = 0;
    int warnings = 0;
    for (const core::Diagnostic& diagnostic : document.diagnostics())
        (diagnostic.severity == core::Severity::Error ? errors : warnings) += 1;
    QVERIFY(errors > 1);
    QCOMPARE(dock.view()->topLevelItemCount(), static_cast<int>(document.diagnostics().size()));
    auto* errorsButton = child<QToolButton>(&dock, "errorsButton");
    QCOMPARE(errorsButton->text(), QString("%1 errors").arg(errors));
    QCOMPARE(child<QToolButton>(&dock, "infoButton")->text(), QString("0 infos"));

    errorsButton->click();
    int shown = 0;
    for (int i = 0; i < dock.view()->topLevelItemCount(); ++i)
        shown += dock.view()->topLevelItem(i)->isHidden() ? 0 : 1;
    QCOMPARE(shown, warnings);

    // The counts follow the model.
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "TRUE")));
    QCOMPARE(errorsButton->text(), QString("%1 errors").arg(errors - 1));
}

void TestDocks::problemFocusesConditionSpan()
{
    Document document;
    Selection selection;
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "TRUE AND Missing")));
    ProblemsDock problems(&document, &selection);
    TransitionDock transitions(&document, &selection);
    QTreeWidgetItem* item = problemItem(problems.view(), "GG203", "A1 → F4");
    QVERIFY(item);
    problems.activate(item);
    QCOMPARE(transitions.transitionId(), QString("A1->F4"));
    const QTextCursor cursor = child<ConditionEdit>(&transitions, "conditionEdit")->textCursor();
    QCOMPARE(cursor.selectionStart(), 9);
    QCOMPARE(cursor.selectionEnd(), 16);
}

void TestDocks::stPreviewShowsProgramAndHighlightsStep()
{
    Document document;
    Selection selection;
    StPreviewDock dock(&document, &selection);
    dock.resize(700, 500);
    dock.show();
    QPlainTextEdit* code = dock.editor();
    QTRY_VERIFY(code->toPlainText().contains("CASE State OF"));
    QVERIFY(code->isReadOnly());

    selection.select(ElementRef::step("A1"));
    const core::StPreview preview = core::previewGemmaProgram(document.model(), core::Dialect::Iec);
    const core::LineRange range = preview.ranges.at("A1");
    QCOMPARE(dock.highlightedRanges(), std::vector<core::LineRange> { range });
    const QList<QTextEdit::ExtraSelection> selections = code->extraSelections();
    QCOMPARE(selections.size(), range.last - range.first + 1);
    QCOMPARE(selections.front().cursor.block().blockNumber(), range.first - 1);
    QCOMPARE(selections.back().cursor.block().blockNumber(), range.last - 1);
    QVERIFY(selections.front().cursor.block().text().contains("A1"));

    // The family transition is highlighted in every F branch.
    selection.select(ElementRef::transition("F->D1"));
    QVERIFY(dock.highlightedRanges().size() > 1);

    // Live: a condition edit shows up.
    declare(document, "Ready_To_Go_42");
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Ready_To_Go_42")));
    QTRY_VERIFY(code->toPlainText().contains("Ready_To_Go_42"));
    selection.clear();
    QVERIFY(code->extraSelections().isEmpty());
}

void TestDocks::stPreviewDialectIsUndoable()
{
    Document document;
    Selection selection;
    declare(document, "Start");
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Start")));
    StPreviewDock dock(&document, &selection);
    dock.show();
    auto* dialect = child<QComboBox>(&dock, "dialectCombo");
    QCOMPARE(dialect->currentData().toInt(), static_cast<int>(core::Dialect::Iec));
    dialect->setCurrentIndex(dialect->findData(static_cast<int>(core::Dialect::Codesys)));
    QCOMPARE(document.model().settings().dialect, core::Dialect::Codesys);
    QTRY_VERIFY(dock.editor()->toPlainText().contains("GVL.Start"));
    document.undoStack()->undo();
    QCOMPARE(dialect->currentData().toInt(), static_cast<int>(core::Dialect::Iec));
    QTRY_VERIFY(!dock.editor()->toPlainText().contains("GVL.Start"));
}

void TestDocks::stPreviewRewritesOnlyWhatChanged()
{
    Document document;
    Selection selection;
    declare(document, "Start");
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Start")));
    StPreviewDock dock(&document, &selection);
    dock.resize(700, 300);
    dock.show();
    QPlainTextEdit* code = dock.editor();
    QTRY_VERIFY(code->toPlainText().contains("CASE State OF"));
    QScrollBar* vertical = code->verticalScrollBar();
    QVERIFY(vertical->maximum() > 10);
    vertical->setValue(vertical->maximum() / 2);
    const int top = vertical->value();

    const auto generated = [&document] {
        const core::Model& model = document.model();
        return QString::fromStdString(core::previewGemmaProgram(model, model.settings().dialect).text);
    };
    // The first change an update makes is its text edit; the highlighter's
    // format changes follow.
    int changedCharacters = -1;
    connect(code->document(), &QTextDocument::contentsChange, &dock, [&](int, int removed, int added) {
        if (changedCharacters < 0)
            changedCharacters = removed + added;
    });

    // One condition: the text is exactly the generated one, a few characters changed, the view stays.
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "NOT Start")));
    QTRY_COMPARE(code->toPlainText(), generated());
    QVERIFY(changedCharacters > 0);
    QVERIFY(changedCharacters < 40);
    QCOMPARE(vertical->value(), top);

    // Shorter again, and a change everywhere (the dialect): still exactly the generated text.
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "")));
    QTRY_COMPARE(code->toPlainText(), generated());
    QVERIFY(document.push(new SetDialectCommand(document, core::Dialect::Codesys)));
    QTRY_COMPARE(code->toPlainText(), generated());
    document.undoStack()->undo();
    QTRY_COMPARE(code->toPlainText(), generated());
    // The rewrites are not an edit history of the read-only preview.
    QVERIFY(!code->document()->isUndoAvailable());
}

void TestDocks::wrappingLabelHeightFollowsTextAndFont()
{
    const QString text = QStringLiteral("In the condition of A1->F4: 'Foo' is not a declared variable, "
                                        "nor is 'Bar', and the condition is empty otherwise.");
    WrappingLabel label(text);
    QLabel plain(text);
    plain.setWordWrap(true);
    QVERIFY(label.wordWrap());
    for (int width : {80, 160, 320, 80, 640, 160})
        QCOMPARE(label.heightForWidth(width), plain.heightForWidth(width));
    const int oneLine = label.heightForWidth(2000);
    QVERIFY(label.heightForWidth(80) > oneLine);

    // A new text, a bigger font: new heights, not the remembered ones.
    label.setText(text + QStringLiteral(" ") + text);
    plain.setText(label.text());
    QCOMPARE(label.heightForWidth(160), plain.heightForWidth(160));
    QFont bigger = label.font();
    bigger.setPointSizeF(bigger.pointSizeF() * 2);
    label.setFont(bigger);
    plain.setFont(bigger);
    QCOMPARE(label.heightForWidth(160), plain.heightForWidth(160));
    QCOMPARE(label.heightForWidth(2000), plain.heightForWidth(2000));
    QVERIFY(label.heightForWidth(2000) > oneLine);
}

void TestDocks::secondaryTextIsReadable()
{
    QVERIFY(qAbs(contrastRatio(Qt::black, Qt::white) - 21.0) < 0.01);
    QVERIFY(qAbs(contrastRatio(Qt::white, Qt::white) - 1.0) < 0.01);
    // Fusion's disabled text on its window, what hints used before: 1.6:1.
    QVERIFY(contrastRatio(QColor(0xbe, 0xbe, 0xbe), QColor(0xef, 0xef, 0xef)) < 1.7);

    QPalette dark;
    dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    dark.setColor(QPalette::WindowText, QColor(0xf0, 0xf0, 0xf0));
    dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    dark.setColor(QPalette::Text, QColor(0xe0, 0xe0, 0xe0));
    for (const QPalette& palette : {QApplication::palette(), dark}) {
        for (QPalette::ColorRole background : {QPalette::Window, QPalette::Base}) {
            const QColor text = palette.color(background == QPalette::Base ? QPalette::Text : QPalette::WindowText);
            const QColor secondary = secondaryTextColor(palette, background);
            QVERIFY(contrastRatio(secondary, palette.color(background)) >= kMinimumTextContrast);
            QVERIFY(secondary != text); // still told apart from the main text
        }
    }

    // The Transition dock's hint lines use it.
    Document document;
    Selection selection;
    TransitionDock dock(&document, &selection);
    selection.select(ElementRef::transition("A1->F4"));
    auto* names = child<QLabel>(&dock, "namesLabel");
    QVERIFY(contrastRatio(names->palette().color(QPalette::WindowText), names->palette().color(QPalette::Window))
            >= kMinimumTextContrast);
    // And the Step dock's "Select a step..." when nothing is selected.
    StepDock steps(&document, &selection);
    selection.clear();
    auto* placeholder = child<QLabel>(&steps, "placeholder");
    QVERIFY(placeholder->isEnabled());
    QVERIFY(contrastRatio(placeholder->palette().color(QPalette::WindowText),
                          placeholder->palette().color(QPalette::Window))
            >= kMinimumTextContrast);
}

void TestDocks::diagnosticTextTranslatesByCode()
{
    core::Diagnostic undeclared;
    undeclared.code = "GG203";
    undeclared.message = "in the condition of A1->F4: 'Foo' is not a declared variable";
    undeclared.arguments = { "A1->F4", "Foo", "'Foo' is not a declared variable" };
    // Transitions named as the chart and the Problems dock's element column name them.
    QCOMPARE(diagnosticText(undeclared),
             QString::fromUtf8("In the condition of A1 \u2192 F4: 'Foo' is not a declared variable."));

    // Arguments the code does not promise: the English message, capitalised.
    undeclared.arguments = { "A1->F4" };
    QCOMPARE(diagnosticText(undeclared),
             QString::fromUtf8("In the condition of A1 \u2192 F4: 'Foo' is not a declared variable"));
    undeclared.message = "F->D1 and F1->A2 overlap";
    QCOMPARE(diagnosticText(undeclared), QString::fromUtf8("F (family) \u2192 D1 and F1 \u2192 A2 overlap"));

    // An empty condition says what to write, or to hide what the machine does not need.
    core::Diagnostic empty;
    empty.code = "GG202";
    empty.message = "the condition of A1->F4 is empty";
    empty.arguments = {"A1->F4"};
    QVERIFY(diagnosticText(empty).startsWith(QString::fromUtf8("The condition of A1 \u2192 F4 is empty")));
    QVERIFY(diagnosticText(empty).contains(QStringLiteral("hide the transition")));

    core::Diagnostic unknown;
    unknown.code = "GG999";
    unknown.message = "something new";
    QCOMPARE(diagnosticText(unknown), QString("Something new"));

    // Every diagnostic the checks produce has a text.
    Document document;
    for (const core::Diagnostic& diagnostic : document.diagnostics())
        QVERIFY(!diagnosticText(diagnostic).isEmpty());
}

void TestDocks::diagnosticTextWordsTheTeacherChecks()
{
    core::Diagnostic runaway;
    runaway.code = "GG423";
    runaway.message = "English";
    runaway.arguments = { "F1", "StepButton", "T1", "T2", "2", "until-stable" };
    QCOMPARE(diagnosticText(runaway),
             QString::fromUtf8("StepButton is read in T1 and by its level in T2, which can fire right after it: while "
                               "StepButton stays TRUE, both fire in the same scan and step 2 of F1 is passed "
                               "through; read its rising edge in T2 (\u2191StepButton) so that each press fires one "
                               "transition."));
    runaway.arguments.back() = "one-per-scan";
    QVERIFY(diagnosticText(runaway).contains("in consecutive scans"));

    core::Diagnostic incomplete;
    incomplete.code = "GG424";
    incomplete.message = "English";
    incomplete.arguments = { "F2", "3", "T3, T4", "CP1 = TRUE, CP2 = TRUE" };
    QCOMPARE(diagnosticText(incomplete),
             QString("The selection after step 3 of F2 is not complete: with CP1 = TRUE, CP2 = TRUE none of T3, T4 "
                     "fires and the GRAFCET waits in step 3; add a branch for these values unless waiting is "
                     "intended."));
}

namespace {

core::Variable packmlVariable(std::string name, core::VariableKind kind = core::VariableKind::Input)
{
    core::Variable variable;
    variable.name = std::move(name);
    variable.kind = kind;
    return variable;
}

// Gives (mode, state) of a PackML model its own GRAFCET: one initial step
// with one action.
void packmlGrafcet(core::Model& model, int mode, core::packml::State state, core::GrafcetAction action)
{
    QVERIFY(model.setGrafcetChoice(mode, state, core::packml::GrafcetChoice::own()));
    core::GrafcetStep step;
    step.initial = true;
    step.actions.push_back(std::move(action));
    QVERIFY(model.addGrafcetStep(core::packml::grafcetKey(mode, state), step));
}

// PackML models that, together, raise every code PM001-PM019.
std::vector<core::Diagnostic> everyPackMLCheck()
{
    using core::packml::Command;
    using core::packml::State;
    using core::packml::StateSet;
    std::vector<core::Diagnostic> all;
    const auto collect = [&](const core::Model& model) {
        for (const core::Diagnostic& d : core::checkModel(model))
            all.push_back(d);
    };

    core::Model settings = core::packml::newModel(core::packml::Edition::Y2022);
    settings.removeMode(1);
    settings.setPackMLInitialState(State::Execute);
    settings.setName("Bad name");
    settings.addMode(4, "4x");
    settings.addMode(5, "Cleaning");
    settings.setModeChangeStates(5, StateSet{});
    settings.setModeDisabled(2, StateSet{State::Stopped, State::Held, State::Unholding});
    settings.setModeChangeStates(3, StateSet{State::Clearing, State::Stopped, State::Idle, State::Aborted});
    settings.setCommandCondition(Command::Stop, "cmd_hold");
    settings.addVariable(packmlVariable("Lamp", core::VariableKind::Output));
    settings.addVariable(packmlVariable("CntrlCmd"));
    settings.setCommandCondition(Command::Start, "Cmd_Start AND Lamp");
    settings.setCommandCondition(Command::Reset, "RE Cmd_Reset");
    settings.setCommandCondition(Command::Unhold, "");
    collect(settings);

    core::Model paths = core::packml::newModel(core::packml::Edition::Y2022);
    paths.setModeChangeStates(1, StateSet{State::Stopped});
    packmlGrafcet(paths, 1, State::Resetting, {core::ActionTiming::OnActivation, "R Complete"});
    packmlGrafcet(paths, 2, State::Aborting, {core::ActionTiming::OnActivation, "R Complete"});
    packmlGrafcet(paths, 1, State::Execute, {core::ActionTiming::OnActivation, "S Complete"});
    packmlGrafcet(paths, 2, State::Clearing, {core::ActionTiming::OnActivation, "S Complete"});
    paths.setModeDisabled(2, StateSet{State::Clearing});
    paths.setGrafcetChoice(2, State::Stopping, core::packml::GrafcetChoice::sameAs(1));
    collect(paths);

    core::Model commands = core::packml::newModel(core::packml::Edition::Y2015);
    for (int mode = 1; mode <= 3; ++mode)
        commands.setModeDisabled(mode, StateSet{State::Holding, State::Held, State::Unholding});
    commands.setCommandCondition(Command::Complete, "Cmd_Stop");
    core::packml::Options options = commands.packml()->options;
    options.completeInSuspendedHeld = true;
    commands.setPackMLOptions(options);
    collect(commands);
    return all;
}

} // namespace

void TestDocks::diagnosticTextWordsEveryPackMLCheck()
{
    std::set<std::string> codes;
    for (core::Diagnostic d : everyPackMLCheck()) {
        codes.insert(d.code);
        d.message = "English";
        // A template for the code and these arguments: the core's English is not what shows.
        QVERIFY2(diagnosticText(d) != QString("English"), d.code.c_str());
    }
    for (int n = 1; n <= 19; ++n)
        QVERIFY2(codes.count(QString("PM%1").arg(n, 3, 10, QChar('0')).toStdString()) == 1, qPrintable(QString::number(n)));

    core::Diagnostic output;
    output.code = "PM012";
    output.target = core::Diagnostic::Target::Command;
    output.element = "Start";
    output.arguments = {"command Start", "Lamp"};
    QCOMPARE(diagnosticText(output),
             QString("The condition of command Start reads the output 'Lamp': commands and mode requests come from an "
                     "operator, a line controller or an alarm, so read an input or an internal variable."));

    // The GEMMA condition errors name a command or request in the UI language too.
    core::Diagnostic undeclared;
    undeclared.code = "GG203";
    undeclared.target = core::Diagnostic::Target::Request;
    undeclared.element = "Manual";
    undeclared.mode = 3;
    undeclared.arguments = {"request of mode Manual", "Key", "'Key' is not a declared variable"};
    QCOMPARE(diagnosticText(undeclared), QString("In the condition of request of mode Manual: 'Key' is not a declared "
                                                 "variable."));
    core::Diagnostic empty;
    empty.code = "GG202";
    empty.target = core::Diagnostic::Target::Command;
    empty.element = "Hold";
    empty.arguments = {"command Hold"};
    QCOMPARE(diagnosticText(empty), QString("The condition of command Hold is empty: write FALSE for a command that "
                                            "comes only through CntrlCmd."));

    core::Diagnostic state;
    state.target = core::Diagnostic::Target::ModeState;
    state.element = "Manual";
    state.state = "Execute";
    QCOMPARE(packmlElementText(state), QString("Manual: Execute"));
}

// The condition parser's errors: every kind worded in English as the core
// words it, and in French in GG201 wherever the editor shows it.
void TestDocks::syntaxErrorsAreInTheUiLanguage()
{
    std::string chain = "a";
    std::string nots;
    for (int i = 0; i < 1001; ++i)
        chain += " AND a";
    for (int i = 0; i < 201; ++i)
        nots += "NOT ";
    const std::vector<std::string> conditions = {
        " ", "a (* x *)", "a := b", "a == b", "a != b", "!a", "a && b", "a | b", "a ** 2", "a;", "a AND \xFF",
        "Temp\xC3\xA9", "x = 16#FF", "GVL.Start", "x > 1.5.3", "IF a", "TIME > 5", "a AND Case", "a AND \x1B",
        "a AND @", chain, std::string(201, '(') + "a", nots + "a", "a)",
        "OR b", "a AND ( )", "a AND", "a AND (b OR)", "a AND ((b)", "x OR (a b)", "a b",
    };
    std::set<core::cond::ParseError::Kind> kinds;
    for (const std::string& condition : conditions) {
        const core::cond::ParseResult parsed = core::cond::parse(condition);
        QVERIFY2(!parsed.ok(), condition.c_str());
        kinds.insert(parsed.error->kind);
        QCOMPARE(conditionErrorText(*parsed.error), QString::fromStdString(parsed.error->message));
    }
    QCOMPARE(kinds.size(), conditions.size() - 1); // two conditions end in OperandAfter
    QCOMPARE(conditionErrorText(core::cond::makeParseError(core::cond::ParseError::Kind::AfterCondition, {}, "x")),
             QString("unexpected 'x' after a complete condition"));

    Document document;
    Selection selection;
    declare(document, "Go");
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "Go AND )")));
    const std::vector<core::Diagnostic> diagnostics = document.diagnosticsFor(ElementRef::transition("A1->F4"));
    QCOMPARE(diagnostics.size(), std::size_t{1});
    const core::Diagnostic& syntax = diagnostics.front();
    QCOMPARE(QString::fromStdString(syntax.code), QString("GG201"));
    QCOMPARE(diagnosticText(syntax),
             QString::fromUtf8("Syntax error in the condition of A1 \u2192 F4: expected an operand after 'AND', found ')'."));

    Translators translators;
    QVERIFY(translators.setLanguage("fr"));
    const QString french = QString::fromUtf8("Erreur de syntaxe dans la r\u00e9ceptivit\u00e9 de A1 \u2192 F4\u00a0: "
                                             "op\u00e9rande attendu apr\u00e8s 'AND', trouv\u00e9 ')'.");
    QCOMPARE(diagnosticText(syntax), french);
    // The condition editor of the Transition dock and the Problems dock show it.
    TransitionDock transitions(&document, &selection);
    ProblemsDock problems(&document, &selection);
    selection.select(ElementRef::transition("A1->F4"));
    auto* edit = child<ConditionEdit>(&transitions, "conditionEdit");
    QCOMPARE(edit->problems().size(), 1);
    QCOMPARE(edit->problems().front().message, french);
    QTreeWidgetItem* item = problemItem(problems.view(), "GG201", "A1 \u2192 F4");
    QVERIFY(item);
    QCOMPARE(item->text(ProblemsDock::MessageColumn), french);

    // A kind this editor does not know (a newer core): the English detail in the translated frame.
    core::Diagnostic newer = syntax;
    newer.arguments[3] = "something-new";
    QVERIFY(diagnosticText(newer).startsWith(QString::fromUtf8("Erreur de syntaxe dans la r\u00e9ceptivit\u00e9")));
    QVERIFY(diagnosticText(newer).contains("expected an operand after 'AND', found ')'"));
}

// The type checker's errors and the value parser's problems: every kind
// worded in English as the core words it, and in French in GG204 and GG304.
void TestDocks::typeAndValueErrorsAreInTheUiLanguage()
{
    const std::vector<core::Variable> variables = {
        {"Go", core::IecType::Bool, "", ""}, {"Speed", core::IecType::Int, "", ""}, {"Temp", core::IecType::Real, "", ""}};
    const core::SymbolTable symbols(variables);
    const char* const conditions[] = {
        "Speed + 1", "NOT Speed", "-Go", "Speed AND Go", "Go + 1 > 0", "Temp MOD 2 > 1", "Go = (Speed * 2.5)",
        "Speed > 9223372036854775808", "Temp < 1e999",
    };
    std::set<core::cond::TypeError::Kind> typeKinds;
    for (const char* condition : conditions) {
        const core::cond::ParseResult parsed = core::cond::parse(condition);
        QVERIFY2(parsed.ok(), condition);
        const std::vector<core::cond::TypeIssue> issues = core::cond::typeCheck(parsed.expression, symbols);
        QCOMPARE(issues.size(), std::size_t{1});
        QVERIFY2(issues.front().error.has_value(), condition);
        typeKinds.insert(issues.front().error->kind);
        QCOMPARE(conditionTypeErrorText(*issues.front().error), QString::fromStdString(issues.front().message));
    }
    QCOMPARE(typeKinds.size(), std::size(conditions));
    // No condition gives an operand of unknown type today; the text stays the core's.
    const core::cond::TypeError unknown{core::cond::TypeError::Kind::NotBoolOperand, "NOT", {"x", "unknown"}, {}};
    QCOMPARE(conditionTypeErrorText(unknown), QString::fromStdString(core::cond::toText(unknown)));

    const std::pair<core::IecType, const char*> values[] = {
        {core::IecType::Int, " 5"},  {core::IecType::Bool, "yes"},  {core::IecType::Int, "abc"},
        {core::IecType::Sint, "abc"}, {core::IecType::Real, "hot"}, {core::IecType::Int, "40000"},
        {core::IecType::Lreal, "1e309"},
    };
    std::set<core::ValueProblem::Kind> valueKinds;
    for (const auto& [type, value] : values) {
        const std::optional<core::ValueProblem> problem = core::valueProblem(type, value);
        QVERIFY2(problem.has_value(), value);
        valueKinds.insert(problem->kind);
        QCOMPARE(valueProblemText(*problem), QString::fromStdString(core::toText(*problem)));
    }
    QCOMPARE(valueKinds.size(), std::size_t{5});

    Document document;
    Selection selection;
    declare(document, "Go");
    declare(document, "BottleCount", core::IecType::Int);
    core::Variable limit;
    limit.name = "Limit";
    limit.type = core::IecType::Int;
    limit.defaultValue = "40000";
    QVERIFY(document.push(new AddVariableCommand(document, limit)));
    QVERIFY(document.push(new SetConditionCommand(document, "A1->F4", "BottleCount AND Go")));
    const std::vector<core::Diagnostic> onTransition = document.diagnosticsFor(ElementRef::transition("A1->F4"));
    QCOMPARE(onTransition.size(), std::size_t{1});
    const core::Diagnostic& typeError = onTransition.front();
    QCOMPARE(QString::fromStdString(typeError.code), QString("GG204"));
    QCOMPARE(diagnosticText(typeError),
             QString::fromUtf8("Type error in the condition of A1 \u2192 F4: AND needs BOOL operands, but 'BottleCount' is INT."));
    std::optional<core::Diagnostic> defaultError;
    for (const core::Diagnostic& diagnostic : document.diagnosticsFor(ElementRef::variable("Limit"))) {
        if (diagnostic.code == "GG304")
            defaultError = diagnostic;
    }
    QVERIFY(defaultError.has_value());
    QCOMPARE(diagnosticText(*defaultError),
             QString("The default value of variable 'Limit' is invalid: '40000' is out of range for INT "
                     "(-32768..32767)."));

    Translators translators;
    QVERIFY(translators.setLanguage("fr"));
    const QString frenchType = QString::fromUtf8("Erreur de type dans la r\u00e9ceptivit\u00e9 de A1 \u2192 F4\u00a0: AND exige "
                                                 "des op\u00e9randes BOOL, mais 'BottleCount' est de type INT.");
    QCOMPARE(diagnosticText(typeError), frenchType);
    QCOMPARE(diagnosticText(*defaultError),
             QString::fromUtf8("La valeur initiale de la variable 'Limit' est invalide\u00a0: '40000' est hors limites "
                               "pour INT (-32768..32767)."));
    // The Problems dock shows them.
    ProblemsDock problems(&document, &selection);
    QTreeWidgetItem* item = problemItem(problems.view(), "GG204", "A1 \u2192 F4");
    QVERIFY(item);
    QCOMPARE(item->text(ProblemsDock::MessageColumn), frenchType);

    // A kind this editor does not know (a newer core): the English detail in the translated frame.
    core::Diagnostic newer = typeError;
    newer.arguments[3] = "something-new";
    QCOMPARE(diagnosticText(newer), QString::fromUtf8("Erreur de type dans la r\u00e9ceptivit\u00e9 de A1 \u2192 F4\u00a0: AND "
                                                      "needs BOOL operands, but 'BottleCount' is INT."));
    newer = *defaultError;
    newer.arguments[3] = "something-new";
    QVERIFY(diagnosticText(newer).endsWith("'40000' is out of range for INT (-32768..32767)."));
}

void TestDocks::objectNamesForSaveState()
{
    Document document;
    Selection selection;
    QCOMPARE(StepDock(&document, &selection).objectName(), QString("stepDock"));
    QCOMPARE(TransitionDock(&document, &selection).objectName(), QString("transitionDock"));
    QCOMPARE(VariablesDock(&document, &selection).objectName(), QString("variablesDock"));
    QCOMPARE(ProblemsDock(&document, &selection).objectName(), QString("problemsDock"));
    QCOMPARE(StPreviewDock(&document, &selection).objectName(), QString("stPreviewDock"));
}

QTEST_MAIN(TestDocks)
// The severity marks are drawings: transparent around, the severity's
// colour in the middle, fainter when disabled, sharp at a device pixel ratio of 2.
void TestDocks::severityIconsAreDrawnOnTransparency()
{
    const std::pair<core::Severity, QColor> expected[] = {
        {core::Severity::Error, QColor(0xd3, 0x2f, 0x2f)},
        {core::Severity::Warning, QColor(0xf9, 0xa8, 0x25)},
        {core::Severity::Info, QColor(0x19, 0x76, 0xd2)},
    };
    for (const auto& [severity, colour] : expected) {
        const QIcon icon = severityIcon(severity);
        QVERIFY(!icon.isNull());
        const QImage image = icon.pixmap(QSize(32, 32)).toImage();
        QCOMPARE(image.size(), QSize(32, 32));
        QCOMPARE(qAlpha(image.pixel(0, 0)), 0);
        QCOMPARE(qAlpha(image.pixel(31, 0)), 0);
        // Lower left of the centre: clear of the mark drawn on the disc or triangle.
        const QColor inside = image.pixelColor(10, 24);
        QCOMPARE(inside, colour);
        const QImage disabled = icon.pixmap(QSize(32, 32), QIcon::Disabled).toImage();
        QVERIFY(disabled.pixelColor(10, 24).alpha() < 255);
        const QPixmap sharp = icon.pixmap(QSize(16, 16), 2.0);
        QCOMPARE(sharp.size(), QSize(32, 32));
        QCOMPARE(sharp.devicePixelRatio(), 2.0);
    }
}

#include "test_docks.moc"
