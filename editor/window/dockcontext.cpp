#include "editor/window/dockcontext.h"

#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>

#include <QAction>

#include <algorithm>
#include <array>
#include <utility>

namespace editor {

namespace {

struct Counterparts {
    const char* chart;
    const char* grafcet;
};
constexpr std::array<Counterparts, 2> kGemmaCounterparts{{
    {"stepDock", "grafcetStepDock"},
    {"transitionDock", "grafcetTransitionDock"},
}};
constexpr std::array<Counterparts, 2> kPackmlCounterparts{{
    {"packmlStateDock", "grafcetStepDock"},
    {"packmlCommandsDock", "grafcetTransitionDock"},
}};
constexpr std::array<Counterparts, 4> kAllCounterparts{{
    kGemmaCounterparts[0], kGemmaCounterparts[1], kPackmlCounterparts[0], kPackmlCounterparts[1]}};

// The docks of one template only; the others (Variables, Problems...) serve both.
constexpr std::array<const char*, 3> kGemmaDocks{"stepDock", "transitionDock", "simulationDock"};
constexpr std::array<const char*, 4> kPackmlDocks{"packmlStateDock", "packmlCommandsDock", "packmlModesDock",
                                                  "packmlSimulationDock"};

template <std::size_t N>
bool contains(const std::array<const char*, N>& names, const QString& name)
{
    return std::any_of(names.begin(), names.end(), [&name](const char* each) { return name == QLatin1String(each); });
}

const std::array<Counterparts, 2>& counterpartsOf(core::TemplateKind kind)
{
    return kind == core::TemplateKind::PackML ? kPackmlCounterparts : kGemmaCounterparts;
}

bool shownInFront(const QDockWidget* dock)
{
    return dock && !dock->isHidden() && !dock->visibleRegion().isEmpty();
}

} // namespace

DockContext::DockContext(QMainWindow* window)
    : QObject(window)
    , m_window(window)
{
}

bool DockContext::isContextDock(const QString& objectName)
{
    for (const Counterparts& pair : kAllCounterparts) {
        if (objectName == QLatin1String(pair.chart) || objectName == QLatin1String(pair.grafcet))
            return true;
    }
    return false;
}

// A dock whose visibility the context sets, so whose closing by the user is kept apart.
bool isTracked(const QString& objectName)
{
    return DockContext::isContextDock(objectName) || contains(kGemmaDocks, objectName)
        || contains(kPackmlDocks, objectName);
}

void DockContext::watch(QDockWidget* dock)
{
    if (isTracked(dock->objectName()))
        dock->installEventFilter(this);
}

void DockContext::unwatch(QDockWidget* dock)
{
    dock->removeEventFilter(this);
}

void DockContext::setClosedDocks(const QStringList& names)
{
    m_closed.clear();
    for (const QString& name : names) {
        if (isTracked(name))
            m_closed << name;
    }
}

void DockContext::setGrafcetInFront(bool grafcetInFront)
{
    m_grafcetInFront = grafcetInFront;
    apply();
}

void DockContext::setTemplate(core::TemplateKind kind)
{
    m_template = kind;
    apply();
}

bool DockContext::isForeign(const QString& objectName) const
{
    return m_template == core::TemplateKind::PackML ? contains(kGemmaDocks, objectName)
                                                    : contains(kPackmlDocks, objectName);
}

void DockContext::apply()
{
    untracked([this] {
        for (QDockWidget* dock : m_window->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
            const bool foreign = isForeign(dock->objectName());
            dock->toggleViewAction()->setVisible(!foreign);
            if (foreign)
                dock->hide();
            else if (!isContextDock(dock->objectName()) && !m_closed.contains(dock->objectName())
                     && (contains(kGemmaDocks, dock->objectName()) || contains(kPackmlDocks, dock->objectName())))
                dock->show();
        }
        for (const Counterparts& pair : counterpartsOf(m_template)) {
            QDockWidget* leaving = dockNamed(QLatin1String(m_grafcetInFront ? pair.chart : pair.grafcet));
            QDockWidget* coming = dockNamed(QLatin1String(m_grafcetInFront ? pair.grafcet : pair.chart));
            const bool leavingWasInFront = shownInFront(leaving);
            if (coming && !m_closed.contains(coming->objectName())) {
                coming->show();
                if (leavingWasInFront)
                    coming->raise();
            }
            if (leaving && !leaving->isFloating())
                leaving->hide();
        }
    });
}

// Explicit shows and hides only: a dock hidden with the window (minimised,
// closing) is not hidden itself.
bool DockContext::eventFilter(QObject* watched, QEvent* event)
{
    auto* dock = qobject_cast<QDockWidget*>(watched);
    if (dock && !m_applying && !event->spontaneous()) {
        const QString name = dock->objectName();
        if (event->type() == QEvent::Hide && dock->isHidden() && !m_closed.contains(name))
            m_closed << name;
        else if (event->type() == QEvent::Show)
            m_closed.removeAll(name);
    }
    return QObject::eventFilter(watched, event);
}

QDockWidget* DockContext::dockNamed(const QString& objectName) const
{
    return m_window->findChild<QDockWidget*>(objectName, Qt::FindDirectChildrenOnly);
}

} // namespace editor
