#include "editor/chart/packml/packmlchartscene.h"

#include "core/templates/packml/packmlconfiguration.h"
#include "core/templates/packml/packmlrules.h"
#include "editor/chart/packml/packmlarrowitem.h"
#include "editor/chart/packml/packmlcharttexts.h"
#include "editor/chart/packml/packmlframeitem.h"
#include "editor/chart/packml/packmlstateitem.h"
#include "core/model/model.h"
#include "editor/selection.h"
#include "editor/text/packmltexts.h"

#include <QGraphicsSceneMouseEvent>
#include <QScopedValueRollback>
#include <QSet>

namespace editor {

namespace {

using core::packml::Command;
using core::packml::State;

bool isChartKind(ElementRef::Kind kind)
{
    return kind == ElementRef::Kind::PackmlState || kind == ElementRef::Kind::PackmlTransition
        || kind == ElementRef::Kind::PackmlCommand;
}

QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

} // namespace

PackmlChartScene::PackmlChartScene(const core::Model* model, Selection* selection, QObject* parent)
    : QGraphicsScene(parent)
    , m_model(model)
    , m_selection(selection)
{
    Q_ASSERT(model && selection);
    connect(m_selection, &Selection::changed, this, &PackmlChartScene::selectFromSelection);
    connect(m_selection, &Selection::elementsChanged, this, &PackmlChartScene::selectFromSelection);
    connect(this, &QGraphicsScene::selectionChanged, this, &PackmlChartScene::onSceneSelectionChanged);
    refresh();
}

PackmlChartScene::~PackmlChartScene()
{
    // ~QGraphicsScene deselects the items it deletes, when this is no longer
    // a PackmlChartScene to hear of it.
    disconnect(this, &QGraphicsScene::selectionChanged, this, nullptr);
}

void PackmlChartScene::buildItems(const core::packml::Options& options)
{
    {
        // Deleting selected items is no choice of the user's.
        const QScopedValueRollback<bool> guard(m_syncingSelection, true);
        clear();
    }
    m_frames.clear();
    m_frameArrows.clear();
    m_states.clear();
    m_transitions.clear();
    m_entries.clear();

    const core::packml::PackmlChartLayout layout = core::packml::chartLayout(options);
    setSceneRect(layout.sceneRect.x, layout.sceneRect.y, layout.sceneRect.width, layout.sceneRect.height);
    for (const core::packml::ChartFrame& frame : layout.frames) {
        auto* item = new PackmlFrameItem(frame);
        addItem(item);
        m_frames << item;
        auto* arrow = new PackmlArrowItem(frame.arrow);
        addItem(arrow);
        m_frameArrows << arrow;
    }
    for (const core::packml::ChartStateBox& box : layout.states) {
        auto* item = new PackmlStateItem(box);
        addItem(item);
        m_states << item;
    }
    for (const core::packml::ChartTransition& transition : layout.transitions) {
        auto* item = new PackmlArrowItem(transition.arrow);
        item->setDashed(transition.transition.optional);
        addItem(item);
        m_transitions << item;
        m_entries.append({transition.transition, item});
    }
    m_builtFor = options;
}

void PackmlChartScene::refresh()
{
    const core::packml::Configuration* configuration = m_model->packml();
    const core::packml::Options options = configuration ? configuration->options : core::packml::Options();
    if (!m_builtFor || *m_builtFor != options)
        buildItems(options);
    if (configuration && !configuration->mode(m_mode)) {
        const core::packml::Mode* initial = configuration->mode(configuration->initialMode);
        m_mode = initial ? initial->number : (configuration->modes.empty() ? 0 : configuration->modes.front().number);
        emit modeChanged(m_mode);
    } else if (!configuration && m_mode != 0) {
        m_mode = 0;
        emit modeChanged(m_mode);
    }
    applyMode();
    emit modesChanged();
    selectFromSelection();
}

void PackmlChartScene::setMode(int number)
{
    const core::packml::Configuration* configuration = m_model->packml();
    const int shown = configuration && configuration->mode(number) ? number : 0;
    if (shown == m_mode)
        return;
    m_mode = shown;
    applyMode();
    followModeInSelection();
    emit modeChanged(m_mode);
}

// A state or transition selected in one mode is the same element in the
// mode now shown, if that mode has it: the docks then show it in this mode.
void PackmlChartScene::followModeInSelection()
{
    const ElementRef current = m_selection->current();
    if (current.kind != ElementRef::Kind::PackmlState && current.kind != ElementRef::Kind::PackmlTransition)
        return;
    QGraphicsItem* item = itemFor(current);
    if (item && item->isVisible())
        m_selection->select(elementOf(item));
    else
        m_selection->clear();
}

QString PackmlChartScene::modeTitle() const
{
    const core::packml::Configuration* configuration = m_model->packml();
    const core::packml::Mode* mode = configuration ? configuration->mode(m_mode) : nullptr;
    if (!mode)
        return {};
    const std::string_view name = mode->displayName();
    return PackmlChartTexts::modeTitle(mode->number,
                                       QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
}

core::packml::StateSet PackmlChartScene::enabledStates() const
{
    const core::packml::Configuration* configuration = m_model->packml();
    const core::packml::Mode* mode = configuration ? configuration->mode(m_mode) : nullptr;
    if (mode)
        return core::packml::enabledStates(mode->disabled).enabled;
    core::packml::StateSet every;
    for (const core::packml::StateInfo& info : core::packml::states())
        every.insert(info.state);
    return every;
}

void PackmlChartScene::applyMode()
{
    const core::packml::StateSet enabled = enabledStates();
    applyToStates(enabled);
    applyToTransitions(enabled);
    applyToFrames(enabled);
    selectFromSelection();
}

void PackmlChartScene::applyToStates(const core::packml::StateSet& enabled)
{
    const core::packml::Configuration* configuration = m_model->packml();
    const bool edition2022 = configuration && configuration->options.edition == core::packml::Edition::Y2022;
    const QString mode = modeTitle();
    const core::packml::Mode* shown = configuration ? configuration->mode(m_mode) : nullptr;
    for (PackmlStateItem* item : std::as_const(m_states)) {
        // The 2022 edition displays Complete as "Completed" (spec §2.1).
        const bool completed = edition2022 && item->state() == State::Complete;
        item->setDisplayName(completed ? QStringLiteral("Completed") : packmltext::stateName(item->state()));
        const bool disabled = !enabled.contains(item->state());
        item->setDisabledInMode(disabled);
        const std::optional<core::packml::GrafcetChoice> grafcet =
            shown ? std::optional(shown->grafcetChoice(item->state())) : std::nullopt;
        item->setToolTip(PackmlChartTexts::stateToolTip(item->state(), item->displayName(), disabled, mode, grafcet));
    }
}

void PackmlChartScene::applyToTransitions(const core::packml::StateSet& enabled)
{
    const core::packml::Configuration* configuration = m_model->packml();
    const core::packml::Options options = configuration ? configuration->options : core::packml::Options();
    const QString mode = modeTitle();
    const QScopedValueRollback<bool> guard(m_syncingSelection, true); // hiding deselects
    for (const TransitionEntry& entry : std::as_const(m_entries)) {
        std::optional<core::packml::Destination> destination;
        for (const core::packml::ModeTransition& exists :
             core::packml::modeTransitionsFrom(entry.transition.source, enabled, options)) {
            if (exists.transition.target == entry.transition.target
                && exists.transition.trigger == entry.transition.trigger)
                destination = exists.destination;
        }
        entry.item->setVisible(destination.has_value());
        entry.item->setGreyed(destination && destination->skipped);
        entry.item->setLabelCandidates(PackmlChartTexts::transitionLabels(entry.transition, destination));
        entry.item->setToolTip(PackmlChartTexts::transitionToolTip(entry.transition, destination, mode));
    }
}

void PackmlChartScene::applyToFrames(const core::packml::StateSet& enabled)
{
    const core::packml::Configuration* configuration = m_model->packml();
    const QString mode = modeTitle();
    for (qsizetype i = 0; i < m_frames.size(); ++i) {
        const Command command = m_frames[i]->command();
        const State target = command == Command::Abort ? State::Aborting : State::Stopping;
        const std::optional<core::packml::Destination> destination = core::packml::destination(target, enabled);
        const QString condition = configuration ? fromStd(configuration->command(command).condition) : QString();
        const std::string_view defaultInput = core::packml::commandInfo(command).defaultInput;
        const bool isDefault = condition.trimmed() == QLatin1String(defaultInput.data(), static_cast<qsizetype>(defaultInput.size()));
        PackmlArrowItem* arrow = m_frameArrows[i];
        arrow->setGreyed(destination && destination->skipped);
        arrow->setLabelCandidates(PackmlChartTexts::frameLabels(command, condition, isDefault, destination));
        arrow->setToolTip(PackmlChartTexts::frameToolTip(command, condition, destination, mode));
    }
}

void PackmlChartScene::retranslate()
{
    applyMode();
}

PackmlStateItem* PackmlChartScene::stateItem(State state) const
{
    for (PackmlStateItem* item : m_states)
        if (item->state() == state)
            return item;
    return nullptr;
}

PackmlArrowItem* PackmlChartScene::transitionItem(State source, State target) const
{
    for (const TransitionEntry& entry : m_entries)
        if (entry.transition.source == source && entry.transition.target == target)
            return entry.item;
    return nullptr;
}

PackmlFrameItem* PackmlChartScene::frameItem(Command command) const
{
    for (PackmlFrameItem* item : m_frames)
        if (item->command() == command)
            return item;
    return nullptr;
}

PackmlArrowItem* PackmlChartScene::frameArrowItem(Command command) const
{
    for (qsizetype i = 0; i < m_frames.size(); ++i)
        if (m_frames[i]->command() == command)
            return m_frameArrows[i];
    return nullptr;
}

std::optional<core::packml::TemplateTransition> PackmlChartScene::transitionOf(const PackmlArrowItem* item) const
{
    for (const TransitionEntry& entry : m_entries)
        if (entry.item == item)
            return entry.transition;
    return std::nullopt;
}

ElementRef PackmlChartScene::elementOf(const QGraphicsItem* item) const
{
    if (const auto* state = qgraphicsitem_cast<const PackmlStateItem*>(item))
        return ElementRef::packmlState(packmltext::stateName(state->state()), m_mode);
    const auto* arrow = qgraphicsitem_cast<const PackmlArrowItem*>(item);
    if (!arrow)
        return {};
    if (const std::optional<core::packml::TemplateTransition> transition = transitionOf(arrow))
        return ElementRef::packmlTransition(packmltext::stateName(transition->source),
                                            packmltext::stateName(transition->target), m_mode);
    for (qsizetype i = 0; i < m_frameArrows.size(); ++i)
        if (m_frameArrows[i] == arrow)
            return ElementRef::packmlCommand(packmltext::commandName(m_frames[i]->command()));
    return {};
}

// By kind and id: the mode an element was selected in does not matter here.
QGraphicsItem* PackmlChartScene::itemFor(const ElementRef& element) const
{
    if (!isChartKind(element.kind))
        return nullptr;
    for (PackmlStateItem* item : m_states) {
        const ElementRef candidate = elementOf(item);
        if (candidate.kind == element.kind && candidate.id == element.id)
            return item;
    }
    for (const QList<PackmlArrowItem*>* arrows : {&m_transitions, &m_frameArrows}) {
        for (PackmlArrowItem* item : *arrows) {
            const ElementRef candidate = elementOf(item);
            if (candidate.kind == element.kind && candidate.id == element.id)
                return item;
        }
    }
    return nullptr;
}

void PackmlChartScene::mouseDoubleClickEvent(QGraphicsSceneMouseEvent* event)
{
    for (QGraphicsItem* item : items(event->scenePos())) {
        if (const auto* state = qgraphicsitem_cast<const PackmlStateItem*>(item)) {
            emit stateDoubleClicked(m_mode, packmltext::stateName(state->state()));
            event->accept();
            return;
        }
    }
    QGraphicsScene::mouseDoubleClickEvent(event);
}

void PackmlChartScene::onSceneSelectionChanged()
{
    if (m_syncingSelection)
        return;
    const QList<QGraphicsItem*> selected = selectedItems();
    if (selected.isEmpty()) {
        if (isChartKind(m_selection->current().kind))
            m_selection->clear();
        return;
    }
    // Several with Ctrl+click: the docks show the one just added, or keep
    // showing the current one while it stays selected (as on the GEMMA chart).
    QList<ElementRef> elements;
    for (QGraphicsItem* item : selected) {
        const ElementRef element = elementOf(item);
        if (!element.isNull())
            elements << element;
    }
    if (elements.isEmpty())
        return;
    ElementRef current = elements.contains(m_selection->current()) ? m_selection->current() : elements.first();
    const QList<ElementRef>& before = m_selection->elements();
    for (const ElementRef& element : std::as_const(elements))
        if (!before.contains(element))
            current = element;
    m_selection->selectMany(elements, current);
}

void PackmlChartScene::selectFromSelection()
{
    QSet<QGraphicsItem*> wanted;
    for (const ElementRef& element : m_selection->elements()) {
        QGraphicsItem* item = itemFor(element);
        if (item && item->isVisible())
            wanted.insert(item);
    }
    const QList<QGraphicsItem*> selected = selectedItems();
    if (QSet<QGraphicsItem*>(selected.begin(), selected.end()) == wanted)
        return;
    const QScopedValueRollback<bool> guard(m_syncingSelection, true);
    clearSelection();
    for (QGraphicsItem* item : std::as_const(wanted))
        item->setSelected(true);
}

} // namespace editor
