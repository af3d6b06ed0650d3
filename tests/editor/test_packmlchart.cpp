// The PackML chart (spec packml.md §2.4): its items, colours, the mode shown
// (disabled states greyed, skipped transitions re-labelled, transitions the
// mode lacks left out), optional transitions dashed, tooltips, selection.

#include "packmlcappermodel.h"
#include "core/formats/modelfiles.h"
#include "core/templates/packml/packmlchartlayout.h"
#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlmodel.h"
#include "editor/chart/chartstyle.h"
#include "editor/chart/packml/packmlarrowitem.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/chart/packml/packmlframeitem.h"
#include "editor/chart/packml/packmlsheetview.h"
#include "editor/chart/packml/packmlstateitem.h"
#include "core/model/model.h"
#include "editor/selection.h"

#include <QComboBox>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace editor;
using core::packml::Command;
using core::packml::State;
using core::packml::StateKind;

namespace {

using packmltest::capper;

using packmltest::kManual;
using packmltest::kProduction;

} // namespace

class TestPackmlChart : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void itemsForEveryStateFrameAndTransition();
    void statesColouredByKind();
    void completeIsCompletedIn2022();
    void templateModeGreysNothing();
    void manualModeGreysExactlyItsDisabledStates();
    void resetFromStoppedSkipsResettingInManual();
    void transitionsTheModeLacksAreLeftOut();
    void frameArrowsNameSkippedTargetAndCondition();
    void optionalTransitionsDashedWithHoldInSuspended();
    void everyItemHasATooltip();
    void longLabelGivesWayToWhereItLeads();
    void modeSelectorListsTheModes();
    void selectorFollowsTheModelsModes();
    void clickSelectsStatesAndTransitions();
    void selectionSelectsTheItem();
    void showingAnotherModeKeepsTheSelectedState();
    void doubleClickOnAStateAsksForItsGrafcet();

private:
    void useModel(const core::Model& model);

    std::unique_ptr<core::Model> m_model;
    std::unique_ptr<Selection> m_selection;
    std::unique_ptr<PackmlChartScene> m_scene;
};

void TestPackmlChart::init()
{
    useModel(capper());
}

void TestPackmlChart::cleanup()
{
    m_scene.reset();
    m_selection.reset();
    m_model.reset();
}

void TestPackmlChart::useModel(const core::Model& model)
{
    cleanup();
    m_model = std::make_unique<core::Model>(model);
    m_selection = std::make_unique<Selection>();
    m_scene = std::make_unique<PackmlChartScene>(m_model.get(), m_selection.get());
}

void TestPackmlChart::itemsForEveryStateFrameAndTransition()
{
    const core::packml::PackmlChartLayout layout = core::packml::chartLayout(m_model->packml()->options);
    QCOMPARE(m_scene->states().size(), 17);
    QCOMPARE(m_scene->frames().size(), 2);
    QCOMPARE(m_scene->transitions().size(), static_cast<qsizetype>(layout.transitions.size()));
    for (const core::packml::ChartTransition& transition : layout.transitions)
        QVERIFY(m_scene->transitionItem(transition.transition.source, transition.transition.target));
    QVERIFY(m_scene->frameItem(Command::Stop) && m_scene->frameItem(Command::Abort));
    QVERIFY(m_scene->frameArrowItem(Command::Stop) && m_scene->frameArrowItem(Command::Abort));
    QCOMPARE(m_scene->frameItem(Command::Stop)->title(), QStringLiteral("Stop"));
    for (const core::packml::ChartStateBox& box : layout.states)
        QCOMPARE(m_scene->stateItem(box.state)->sceneBoundingRect().center(),
                 QPointF(box.box.center().x, box.box.center().y));
}

void TestPackmlChart::statesColouredByKind()
{
    m_scene->setMode(0); // no state greyed
    const QColor wait = chartstyle::packmlStateFillColor(StateKind::Wait);
    const QColor acting = chartstyle::packmlStateFillColor(StateKind::Acting);
    const QColor dual = chartstyle::packmlStateFillColor(StateKind::Dual);
    QVERIFY(wait != acting && acting != dual && wait != dual);
    QCOMPARE(m_scene->stateItem(State::Execute)->fillColor(), dual);
    QCOMPARE(dual, QColor(Qt::white)); // Execute white, as seed 002's figure
    int waits = 0;
    int actings = 0;
    for (const PackmlStateItem* item : m_scene->states()) {
        const StateKind kind = core::packml::stateInfo(item->state()).kind;
        QCOMPARE(item->fillColor(), chartstyle::packmlStateFillColor(kind));
        waits += kind == StateKind::Wait;
        actings += kind == StateKind::Acting;
    }
    QCOMPARE(waits, 6);
    QCOMPARE(actings, 10);
    // Cyan and green: blue, resp. green, the strongest component.
    QVERIFY(wait.blue() > wait.red() && wait.green() > wait.red());
    QVERIFY(acting.green() > acting.red() && acting.green() > acting.blue());
}

void TestPackmlChart::completeIsCompletedIn2022()
{
    QCOMPARE(m_scene->stateItem(State::Complete)->displayName(), QStringLiteral("Complete"));
    useModel(core::packml::newModel(core::packml::Edition::Y2022));
    QCOMPARE(m_scene->stateItem(State::Complete)->displayName(), QStringLiteral("Completed"));
}

void TestPackmlChart::templateModeGreysNothing()
{
    m_scene->setMode(0);
    QCOMPARE(m_scene->mode(), 0);
    for (const PackmlStateItem* item : m_scene->states())
        QVERIFY(!item->isDisabledInMode());
    for (const PackmlArrowItem* item : m_scene->transitions()) {
        QVERIFY(item->isVisible());
        QVERIFY(!item->isGreyed());
    }
}

void TestPackmlChart::manualModeGreysExactlyItsDisabledStates()
{
    QCOMPARE(m_scene->mode(), kProduction); // the initial mode first
    QSignalSpy modeChanged(m_scene.get(), &PackmlChartScene::modeChanged);
    m_scene->setMode(kManual);
    QCOMPARE(m_scene->mode(), kManual);
    QCOMPARE(modeChanged.size(), 1);
    // Spec §6.6: Manual enables only the four states that cannot be disabled.
    const core::packml::StateSet enabled{State::Stopped, State::Idle, State::Execute, State::Aborted};
    for (const PackmlStateItem* item : m_scene->states()) {
        QCOMPARE(item->isDisabledInMode(), !enabled.contains(item->state()));
        QCOMPARE(item->fillColor() == chartstyle::packmlDisabledFillColor(), item->isDisabledInMode());
    }
    // Back in Production, Resetting and Held are enabled again.
    m_scene->setMode(kProduction);
    QVERIFY(!m_scene->stateItem(State::Resetting)->isDisabledInMode());
    QVERIFY(!m_scene->stateItem(State::Held)->isDisabledInMode());
    QVERIFY(m_scene->stateItem(State::Holding)->isDisabledInMode());
}

void TestPackmlChart::resetFromStoppedSkipsResettingInManual()
{
    PackmlArrowItem* reset = m_scene->transitionItem(State::Stopped, State::Resetting);
    QVERIFY(reset);
    QCOMPARE(reset->displayedLabel(), QStringLiteral("Reset")); // Production enables Resetting
    QVERIFY(!reset->isGreyed());
    m_scene->setMode(kManual);
    QVERIFY(reset->isVisible());
    QVERIFY(reset->isGreyed());
    QCOMPARE(reset->labelCandidates().first(), QStringLiteral("Reset → Idle"));
    QVERIFY(reset->displayedLabel().contains(QStringLiteral("Idle")));
    QVERIFY(reset->toolTip().contains(QStringLiteral("3 Manual")));
    QVERIFY(reset->toolTip().contains(QStringLiteral("Idle")));
    // Production skips Starting: Start leads to Execute.
    m_scene->setMode(kProduction);
    QCOMPARE(m_scene->transitionItem(State::Idle, State::Starting)->labelCandidates().first(),
             QStringLiteral("Start → Execute"));
}

void TestPackmlChart::transitionsTheModeLacksAreLeftOut()
{
    m_scene->setMode(kManual);
    // From a disabled state, and to a disabled wait state (Hold with Holding and Held disabled).
    QVERIFY(!m_scene->transitionItem(State::Resetting, State::Idle)->isVisible());
    QVERIFY(!m_scene->transitionItem(State::Execute, State::Holding)->isVisible());
    QVERIFY(!m_scene->transitionItem(State::Execute, State::Completing)->isVisible());
    QVERIFY(m_scene->transitionItem(State::Aborted, State::Clearing)->isVisible());
    m_scene->setMode(kProduction);
    // Production enables Held: Hold leads there, Holding skipped.
    PackmlArrowItem* hold = m_scene->transitionItem(State::Execute, State::Holding);
    QVERIFY(hold->isVisible());
    QCOMPARE(hold->labelCandidates().first(), QStringLiteral("Hold → Held"));
    QVERIFY(!m_scene->transitionItem(State::Held, State::Unholding)->labelCandidates().isEmpty());
}

void TestPackmlChart::frameArrowsNameSkippedTargetAndCondition()
{
    m_scene->setMode(kManual);
    const PackmlArrowItem* stop = m_scene->frameArrowItem(Command::Stop);
    QCOMPARE(stop->labelCandidates(), QStringList{QStringLiteral("Stop → Stopped")}); // default condition
    QVERIFY(stop->isGreyed());
    const PackmlArrowItem* abort = m_scene->frameArrowItem(Command::Abort);
    QCOMPARE(abort->labelCandidates().first(), QStringLiteral("Abort → Aborted: Cmd_Abort OR NOT EStopOK"));
    QVERIFY(abort->displayedLabel().startsWith(QStringLiteral("Abort → Aborted: Cmd_Abort")));
    QVERIFY(abort->toolTip().contains(QStringLiteral("Cmd_Abort OR NOT EStopOK")));
    m_scene->setMode(0);
    QCOMPARE(m_scene->frameArrowItem(Command::Stop)->displayedLabel(), QStringLiteral("Stop"));
    QVERIFY(!m_scene->frameArrowItem(Command::Stop)->isGreyed());
}

void TestPackmlChart::optionalTransitionsDashedWithHoldInSuspended()
{
    useModel(core::packml::newModel(core::packml::Edition::Y2015));
    QVERIFY(!m_scene->transitionItem(State::Suspended, State::Holding));
    for (const PackmlArrowItem* item : m_scene->transitions())
        QVERIFY(!item->isDashed());
    core::packml::Options options = m_model->packml()->options;
    options.holdInSuspended = true;
    QVERIFY(m_model->setPackMLOptions(options));
    m_scene->refresh();
    PackmlArrowItem* hold = m_scene->transitionItem(State::Suspended, State::Holding);
    QVERIFY(hold);
    QVERIFY(hold->isDashed());
    QCOMPARE(hold->displayedLabel(), QStringLiteral("Hold"));
    int dashed = 0;
    for (const PackmlArrowItem* item : m_scene->transitions())
        dashed += item->isDashed();
    QCOMPARE(dashed, 1);
}

void TestPackmlChart::everyItemHasATooltip()
{
    for (const int mode : {0, kProduction, kManual}) {
        m_scene->setMode(mode);
        for (const PackmlStateItem* item : m_scene->states()) {
            QVERIFY(item->toolTip().contains(item->displayName()));
            QVERIFY(item->toolTip().size() > item->displayName().size() + 20);
        }
        for (const PackmlArrowItem* item : m_scene->transitions())
            QVERIFY(!item->toolTip().isEmpty());
        for (const Command command : {Command::Stop, Command::Abort})
            QVERIFY(!m_scene->frameArrowItem(command)->toolTip().isEmpty());
    }
    // What runs in a state: the Capper's Production has its own GRAFCET in
    // Execute, Manual none (the skeleton waits).
    m_scene->setMode(kProduction);
    QVERIFY(m_scene->stateItem(State::Execute)->toolTip().contains(QStringLiteral("its own nested GRAFCET")));
    QVERIFY(!m_scene->stateItem(State::Idle)->toolTip().contains(QStringLiteral("GRAFCET")));
    m_scene->setMode(kManual);
    QVERIFY(m_scene->stateItem(State::Execute)->toolTip().contains(QStringLiteral("waits for a command")));
    QVERIFY(m_scene->stateItem(State::Holding)->toolTip().contains(QStringLiteral("3 Manual")));
    QVERIFY(!m_scene->stateItem(State::Idle)->toolTip().contains(QStringLiteral("3 Manual")));
}

void TestPackmlChart::longLabelGivesWayToWhereItLeads()
{
    m_scene->setMode(kProduction);
    // "Unhold → Execute" is wider than the 76-unit label: the arrow says "→ Execute".
    PackmlArrowItem* unhold = m_scene->transitionItem(State::Held, State::Unholding);
    QCOMPARE(unhold->labelCandidates(),
             (QStringList{QStringLiteral("Unhold → Execute"), QStringLiteral("→ Execute")}));
    QCOMPARE(unhold->displayedLabel(), QStringLiteral("→ Execute"));
    QVERIFY(unhold->toolTip().contains(QStringLiteral("Execute")));
    // A command name a little wider than the label is drawn a little smaller, whole.
    useModel(core::packml::newModel(core::packml::Edition::Y2015));
    PackmlArrowItem* unsuspend = m_scene->transitionItem(State::Suspended, State::Unsuspending);
    QCOMPARE(unsuspend->displayedLabel(), QStringLiteral("Unsuspend"));
    QVERIFY(unsuspend->labelScale() >= PackmlArrowItem::kMinLabelScale);
    QCOMPARE(m_scene->transitionItem(State::Idle, State::Starting)->labelScale(), 1.0);
}

void TestPackmlChart::modeSelectorListsTheModes()
{
    PackmlChartView view(m_scene.get());
    QComboBox* selector = view.modeSelector();
    QStringList titles;
    for (int i = 0; i < selector->count(); ++i)
        titles << selector->itemText(i);
    QCOMPARE(titles, (QStringList{QStringLiteral("1 Production"), QStringLiteral("3 Manual")}));
    QCOMPARE(selector->currentText(), QStringLiteral("1 Production"));
    selector->setCurrentIndex(1);
    emit selector->activated(1);
    QCOMPARE(m_scene->mode(), kManual);
    m_scene->setMode(kProduction);
    QCOMPARE(selector->currentText(), QStringLiteral("1 Production"));
}

void TestPackmlChart::selectorFollowsTheModelsModes()
{
    PackmlChartView view(m_scene.get());
    m_scene->setMode(kManual);
    QVERIFY(m_model->addMode(7, "Cleaning"));
    m_scene->refresh();
    QCOMPARE(view.modeSelector()->count(), 3);
    QCOMPARE(view.modeSelector()->itemText(2), QStringLiteral("7 Cleaning"));
    QCOMPARE(view.modeSelector()->currentText(), QStringLiteral("3 Manual"));
    // The mode shown is removed: the chart shows the initial mode.
    QVERIFY(m_model->removeMode(kManual));
    m_scene->refresh();
    QCOMPARE(m_scene->mode(), kProduction);
    QCOMPARE(view.modeSelector()->currentText(), QStringLiteral("1 Production"));
    QVERIFY(m_scene->stateItem(State::Holding)->isDisabledInMode());
    // A number the model has no mode for shows the bare template.
    m_scene->setMode(kManual);
    QCOMPARE(m_scene->mode(), 0);
    QVERIFY(!m_scene->stateItem(State::Holding)->isDisabledInMode());
}

void TestPackmlChart::clickSelectsStatesAndTransitions()
{
    PackmlChartView view(m_scene.get());
    view.resize(1100, 900);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    PackmlSheetView* sheet = view.sheetView();
    const QPoint execute = sheet->mapFromScene(m_scene->stateItem(State::Execute)->sceneBoundingRect().center());
    QTest::mouseClick(sheet->viewport(), Qt::LeftButton, {}, execute);
    QCOMPARE(m_selection->current(), ElementRef::packmlState(QStringLiteral("Execute"), kProduction));
    QVERIFY(m_scene->stateItem(State::Execute)->isSelected());

    const core::packml::PackmlChartLayout layout = core::packml::chartLayout(m_model->packml()->options);
    const core::Point bar = layout.transition(State::Stopped, State::Resetting)->arrow.barCenter;
    QTest::mouseClick(sheet->viewport(), Qt::LeftButton, {}, sheet->mapFromScene(QPointF(bar.x, bar.y)));
    QCOMPARE(m_selection->current(),
             ElementRef::packmlTransition(QStringLiteral("Stopped"), QStringLiteral("Resetting"), kProduction));

    const core::Point abortBar = layout.frame(Command::Abort)->arrow.barCenter;
    QTest::mouseClick(sheet->viewport(), Qt::LeftButton, {}, sheet->mapFromScene(QPointF(abortBar.x, abortBar.y)));
    QCOMPARE(m_selection->current(), ElementRef::packmlCommand(QStringLiteral("Abort")));

    // The empty sheet, inside the Stop frame: nothing selected.
    const QRectF idle = m_scene->stateItem(State::Idle)->sceneBoundingRect();
    QTest::mouseClick(sheet->viewport(), Qt::LeftButton, {}, sheet->mapFromScene(idle.center() + QPointF(0, -60)));
    QVERIFY(m_selection->current().isNull());
}

void TestPackmlChart::selectionSelectsTheItem()
{
    m_selection->select(ElementRef::packmlState(QStringLiteral("Idle"), kProduction));
    QVERIFY(m_scene->stateItem(State::Idle)->isSelected());
    m_selection->select(ElementRef::packmlTransition(QStringLiteral("Idle"), QStringLiteral("Starting")));
    QVERIFY(!m_scene->stateItem(State::Idle)->isSelected());
    QVERIFY(m_scene->transitionItem(State::Idle, State::Starting)->isSelected());
    m_selection->select(ElementRef::packmlCommand(QStringLiteral("Stop")));
    QVERIFY(m_scene->frameArrowItem(Command::Stop)->isSelected());
    QCOMPARE(m_scene->selectedItems().size(), 1);
    m_selection->clear();
    QVERIFY(m_scene->selectedItems().isEmpty());
}

void TestPackmlChart::showingAnotherModeKeepsTheSelectedState()
{
    m_selection->select(ElementRef::packmlState(QStringLiteral("Execute"), kProduction));
    m_scene->setMode(kManual);
    QCOMPARE(m_selection->current(), ElementRef::packmlState(QStringLiteral("Execute"), kManual));
    // A transition Manual does not have is no longer selected.
    m_scene->setMode(kProduction);
    m_selection->select(ElementRef::packmlTransition(QStringLiteral("Resetting"), QStringLiteral("Idle"), kProduction));
    m_scene->setMode(kManual);
    QVERIFY(m_selection->current().isNull());
}

void TestPackmlChart::doubleClickOnAStateAsksForItsGrafcet()
{
    PackmlChartView view(m_scene.get());
    view.resize(1100, 900);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy opened(&view, &PackmlChartView::stateDoubleClicked);
    PackmlSheetView* sheet = view.sheetView();
    const QPoint resetting = sheet->mapFromScene(m_scene->stateItem(State::Resetting)->sceneBoundingRect().center());
    QTest::mouseDClick(sheet->viewport(), Qt::LeftButton, {}, resetting);
    QCOMPARE(opened.size(), 1);
    QCOMPARE(opened.first().at(0).toInt(), kProduction);
    QCOMPARE(opened.first().at(1).toString(), QStringLiteral("Resetting"));
}

QTEST_MAIN(TestPackmlChart)
#include "test_packmlchart.moc"
