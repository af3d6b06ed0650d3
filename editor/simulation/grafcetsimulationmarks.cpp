#include "editor/simulation/grafcetsimulationmarks.h"

#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetstepitem.h"
#include "editor/grafcet/grafcettransitionitem.h"
#include "editor/grafcet/grafcetwiringitem.h"
#include "editor/simulation/grafcetmarklabelitem.h"
#include "editor/simulation/simulationsession.h"
#include "editor/simulation/simulationtext.h"

#include "core/layout/grafcetlayout.h"
#include "core/simulation/simulator.h"

#include <QLocale>

#include <algorithm>

namespace editor {

namespace {

// Room above the drawing for the caption, while there is one.
constexpr double kCaptionBand = 28;
constexpr double kTimerGap = 1; // between a receptivity and its timers

// Seconds with the decimals the value needs: "2", "1.5", "0.25".
QString secondsText(std::int64_t ms, int minDecimals)
{
    static constexpr std::int64_t kUnit[] = {1000, 100, 10}; // ms per last digit, by decimals
    int decimals = minDecimals;
    while (decimals < 3 && ms % kUnit[decimals] != 0)
        ++decimals;
    return QLocale().toString(static_cast<double>(ms) / 1000.0, 'f', decimals);
}

} // namespace

bool grafcetRuns(const core::Simulator& simulator, std::string_view stepId)
{
    return simulator.hasGrafcet(stepId) && simulator.activeStepId() == stepId && !simulator.entry();
}

GrafcetSimulationMarks::GrafcetSimulationMarks(GrafcetSimulationSource source, GrafcetScene* scene, QObject* parent)
    : QObject(parent)
    , m_source(std::move(source))
    , m_scene(scene)
{
    setObjectName(QStringLiteral("grafcetSimulationMarks"));
    connect(m_scene, &GrafcetScene::rebuilt, this, [this] {
        forgetItems();
        update();
    });
    update();
}

GrafcetSimulationMarks::GrafcetSimulationMarks(SimulationSession* session, GrafcetScene* scene, QObject* parent)
    : GrafcetSimulationMarks(
          [session, scene] {
              GrafcetSimulationSnapshot shown;
              const core::Simulator* simulator = session->simulator();
              const std::string stepId = scene->stepId().toStdString();
              shown.engine = simulator ? simulator->grafcetEngine(stepId) : nullptr;
              if (!shown.engine) // no simulation, or a step the simulator runs no GRAFCET for (hidden)
                  return shown;
              shown.runs = grafcetRuns(*simulator, stepId);
              shown.justEntered = !shown.runs && simulator->activeStepId() == stepId;
              // Transitions fired in the last scan: only a GRAFCET that ran in it has any.
              if (shown.runs)
                  shown.fired = simulator->firedNestedTransitions(stepId);
              shown.owner = scene->stepId();
              return shown;
          },
          scene, parent)
{
    connect(session, &SimulationSession::activeChanged, this, &GrafcetSimulationMarks::update);
    connect(session, &SimulationSession::stepped, this, &GrafcetSimulationMarks::update);
    connect(session, &SimulationSession::historyMoved, this, &GrafcetSimulationMarks::update);
}

QString GrafcetSimulationMarks::captionText() const
{
    return m_caption ? m_caption->text() : QString();
}

void GrafcetSimulationMarks::forgetItems()
{
    // Deleted with the scene's other items.
    m_caption = nullptr;
    m_timers.clear();
    m_state = State::Off;
}

void GrafcetSimulationMarks::clear()
{
    for (const core::GrafcetStepLayout& step : m_scene->layout().steps) {
        if (GrafcetStepItem* item = m_scene->stepItem(step.number)) {
            item->setSimulationMark(GrafcetStepItem::SimulationMark::None);
            item->setLitActions({});
        }
    }
    for (const core::GrafcetTransitionLayout& transition : m_scene->layout().transitions) {
        if (GrafcetTransitionItem* item = m_scene->transitionItem(transition.number))
            item->setFired(false);
    }
    if (GrafcetWiringItem* wiring = m_scene->wiringItem())
        wiring->setFiredTransitions({});
    qDeleteAll(m_timers);
    m_timers.clear();
    delete m_caption;
    m_caption = nullptr;
    m_scene->setSceneRect(m_scene->drawingRect());
    m_state = State::Off;
}

void GrafcetSimulationMarks::update()
{
    const GrafcetSimulationSnapshot shown = m_source();
    const core::NestedEngine* engine = shown.engine;
    if (!engine) {
        if (m_state != State::Off)
            clear();
        return;
    }
    const bool runs = shown.runs;
    m_state = runs ? State::Running : State::Frozen;
    const QString& id = shown.owner;

    // Steps: the token, and the continuous actions the last call emitted.
    const auto running = GrafcetStepItem::SimulationMark::Active;
    const auto frozen = GrafcetStepItem::SimulationMark::Frozen;
    for (const core::GrafcetStepLayout& step : m_scene->layout().steps) {
        GrafcetStepItem* item = m_scene->stepItem(step.number);
        if (!item)
            continue;
        const bool active = engine->active(step.number);
        item->setSimulationMark(!active ? GrafcetStepItem::SimulationMark::None : runs ? running : frozen);
        QList<int> lit;
        if (runs && active) {
            for (const core::GrafcetActionLayout& action : step.actions) {
                if (action.timing == core::ActionTiming::Continuous && engine->emitting(step.number, action.index))
                    lit << action.index;
            }
        }
        item->setLitActions(lit);
    }

    QList<int> fired;
    if (runs) {
        for (int number : shown.fired)
            fired << number;
    }
    for (const core::GrafcetTransitionLayout& transition : m_scene->layout().transitions) {
        if (GrafcetTransitionItem* item = m_scene->transitionItem(transition.number))
            item->setFired(fired.contains(transition.number));
    }
    if (GrafcetWiringItem* wiring = m_scene->wiringItem())
        wiring->setFiredTransitions(fired);

    showTimers(*engine);

    // The caption above the drawing.
    if (runs && engine->unstable())
        setCaption(tr("%1 is active: its GRAFCET runs. Unstable: the last scan ended without a stable situation")
                       .arg(id),
                   true);
    else if (runs)
        setCaption(tr("%1 is active: its GRAFCET runs (step(s) %2)", nullptr,
                      static_cast<int>(engine->activeSteps().size()))
                       .arg(id, stepNumbersText(engine->activeSteps())),
                   false);
    else if (shown.justEntered && shown.resumes)
        setCaption(tr("%1 has just been resumed: its GRAFCET goes on where it was paused in the next scan").arg(id), false);
    else if (shown.justEntered)
        setCaption(tr("%1 has just been entered: its GRAFCET starts from its initial steps in the next scan")
                       .arg(id),
                   false);
    else
        setCaption(tr("%1 is not active: its GRAFCET is shown greyed, as it was left").arg(id), false);
}

// Under each receptivity that reads a timer of an active step, the timer's
// elapsed and preset time: "1.25 / 2 s" ("X5 1.25 / 2 s · X6 0.4 / 3 s"
// for a receptivity that reads two).
void GrafcetSimulationMarks::showTimers(const core::NestedEngine& engine)
{
    QHash<int, QStringList> texts;
    QHash<int, bool> allElapsed;
    if (m_state == State::Running) {
        const std::vector<core::NestedTimerState> timers = engine.timers();
        for (const core::NestedTransition& transition : engine.grafcet().transitions) {
            std::vector<int> read; // timer indices, each once
            for (const auto& [node, timer] : transition.timerOfNode) {
                (void)node;
                if (std::find(read.begin(), read.end(), timer) == read.end())
                    read.push_back(timer);
            }
            std::sort(read.begin(), read.end());
            QStringList parts;
            bool elapsed = true;
            for (int index : read) {
                const core::NestedTimerState& timer = timers[static_cast<std::size_t>(index)];
                if (!engine.active(timer.step))
                    continue;
                QString text = QStringLiteral("%1 / %2 s")
                                   .arg(secondsText(timer.elapsedMs, 2), secondsText(timer.durationMs, 0));
                if (read.size() > 1)
                    text = QStringLiteral("X%1 %2").arg(timer.step).arg(text);
                parts << text;
                elapsed = elapsed && timer.done;
            }
            if (!parts.isEmpty()) {
                texts.insert(transition.number, parts);
                allElapsed.insert(transition.number, elapsed);
            }
        }
    }
    for (auto it = m_timers.begin(); it != m_timers.end();) {
        if (!texts.contains(it.key())) {
            delete it.value();
            it = m_timers.erase(it);
        } else {
            ++it;
        }
    }
    for (auto it = texts.cbegin(); it != texts.cend(); ++it) {
        const GrafcetTransitionItem* transition = m_scene->transitionItem(it.key());
        if (!transition)
            continue;
        GrafcetMarkLabelItem*& label = m_timers[it.key()];
        if (!label) {
            label = new GrafcetMarkLabelItem(GrafcetMarkLabelItem::Kind::Timer);
            label->setTransition(it.key());
            m_scene->addItem(label);
            const core::Rect& receptivity = transition->layout().labelRect;
            label->setPos(receptivity.x, receptivity.bottom() + kTimerGap);
        }
        label->setText(it.value().join(QStringLiteral(" · ")), allElapsed.value(it.key())
                                                                   ? GrafcetMarkLabelItem::Tone::Elapsed
                                                                   : GrafcetMarkLabelItem::Tone::Running);
    }
}

void GrafcetSimulationMarks::setCaption(const QString& text, bool warning)
{
    if (!m_caption) {
        m_caption = new GrafcetMarkLabelItem(GrafcetMarkLabelItem::Kind::Caption);
        m_scene->addItem(m_caption);
    }
    const QRectF drawing = m_scene->drawingRect();
    m_caption->setText(text, warning                        ? GrafcetMarkLabelItem::Tone::Warning
                             : m_state == State::Running ? GrafcetMarkLabelItem::Tone::Running
                                                         : GrafcetMarkLabelItem::Tone::Neutral);
    m_caption->setPos(drawing.left() + core::kGrafcetMargin, drawing.top() - kCaptionBand + 4);
    // The scene grows upwards (and sideways for a caption wider than a narrow drawing).
    const QRectF caption = m_caption->mapRectToScene(m_caption->boundingRect());
    m_scene->setSceneRect(drawing.adjusted(0, -kCaptionBand, 0, 0)
                              .united(caption.adjusted(0, 0, core::kGrafcetMargin, 0)));
}

} // namespace editor
