#include "editor/chart/packml/packmlchartcontextmenu.h"

#include "editor/chart/packml/packmlchartbinding.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/document.h"
#include "editor/selection.h"

#include "core/templates/packml/packmlconfiguration.h"

#include <QActionGroup>
#include <QMenu>

namespace editor {

namespace {

QAction* addNamed(QMenu* menu, const char* name, const QString& text)
{
    QAction* action = menu->addAction(text);
    action->setObjectName(QLatin1String(name));
    return action;
}

// The command a transition element ("Idle->Starting") fires on; empty for a State Complete one.
QString commandOfTransition(const ElementRef& element, const core::packml::Options& options)
{
    const QStringList ends = element.id.split(QStringLiteral("->"));
    if (ends.size() != 2)
        return {};
    const auto source = core::packml::findState(ends[0].toStdString());
    const auto target = core::packml::findState(ends[1].toStdString());
    if (!source || !target)
        return {};
    for (const core::packml::TemplateTransition& transition : core::packml::transitionsFrom(*source, options)) {
        if (transition.target == *target && transition.trigger == core::packml::Trigger::Command) {
            const std::string_view name = core::packml::commandName(transition.command);
            return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
        }
    }
    return {};
}

} // namespace

PackmlChartContextMenu::PackmlChartContextMenu(Document& document, PackmlChartScene& scene, SheetActions sheet,
                                               QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_scene(scene)
    , m_sheet(sheet)
{
}

void PackmlChartContextMenu::populate(QMenu* menu, const ElementRef& element)
{
    const core::packml::Configuration* configuration = m_document.model().packml();
    if (!configuration)
        return;
    switch (element.kind) {
    case ElementRef::Kind::PackmlState:
        addStateEntries(menu, element);
        break;
    case ElementRef::Kind::PackmlTransition:
        if (const QString command = commandOfTransition(element, configuration->options); !command.isEmpty())
            addCommandEntries(menu, command);
        break;
    case ElementRef::Kind::PackmlCommand:
        addCommandEntries(menu, element.id);
        break;
    default:
        if (m_sheet.fit)
            menu->addAction(m_sheet.fit);
        if (m_sheet.exportChart)
            menu->addAction(m_sheet.exportChart);
        break;
    }
    menu->addSeparator();
    addModeEntries(menu);
}

void PackmlChartContextMenu::addStateEntries(QMenu* menu, const ElementRef& element)
{
    const auto state = core::packml::findState(element.id.toStdString());
    if (!state || !core::packml::holdsGrafcet(*state))
        return;
    const QString key = PackmlChartBinding::runningGrafcet(m_document, element.number, element.id);
    if (!key.isEmpty()) {
        QAction* open = addNamed(menu, "openGrafcetAction", tr("&Open GRAFCET"));
        connect(open, &QAction::triggered, this, [this, key] { emit openGrafcetRequested(key); });
    }
    QAction* choose = addNamed(menu, "chooseGrafcetAction", tr("&Choose Its GRAFCET…"));
    choose->setStatusTip(tr("Its own GRAFCET in this mode, the one of another mode, or none"));
    connect(choose, &QAction::triggered, this,
            [this, element] { m_scene.selection()->select(element, QStringLiteral("grafcet")); });
}

void PackmlChartContextMenu::addCommandEntries(QMenu* menu, const QString& command)
{
    QAction* edit = addNamed(menu, "editCommandConditionAction", tr("Edit the %1 &Condition…").arg(command));
    connect(edit, &QAction::triggered, this, [this, command] {
        m_scene.selection()->select(ElementRef::packmlCommand(command), QStringLiteral("condition"));
    });
}

// "Show in Mode": the chart's mode selector, at hand.
void PackmlChartContextMenu::addModeEntries(QMenu* menu)
{
    QMenu* modes = menu->addMenu(tr("Show in &Mode"));
    modes->setObjectName(QStringLiteral("showInModeMenu"));
    auto* group = new QActionGroup(modes);
    for (const core::packml::Mode& mode : m_document.model().packml()->modes) {
        const std::string_view name = mode.displayName();
        QAction* choice = modes->addAction(
            QStringLiteral("%1 %2").arg(mode.number).arg(QString::fromUtf8(name.data(), qsizetype(name.size()))));
        choice->setObjectName(QStringLiteral("showMode_%1").arg(mode.number));
        choice->setCheckable(true);
        choice->setChecked(m_scene.mode() == mode.number);
        group->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, number = mode.number] { m_scene.setMode(number); });
    }
}

} // namespace editor
