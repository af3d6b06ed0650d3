#include "editor/window/dockcontext.h"

#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>

#include <array>
#include <utility>

namespace editor {

namespace {

struct Counterparts {
    const char* chart;
    const char* grafcet;
};
constexpr std::array<Counterparts, 2> kCounterparts{{
    {"stepDock", "grafcetStepDock"},
    {"transitionDock", "grafcetTransitionDock"},
}};

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
    for (const Counterparts& pair : kCounterparts) {
        if (objectName == QLatin1String(pair.chart) || objectName == QLatin1String(pair.grafcet))
            return true;
    }
    return false;
}

void DockContext::watch(QDockWidget* dock)
{
    if (isContextDock(dock->objectName()))
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
        if (isContextDock(name))
            m_closed << name;
    }
}

void DockContext::setGrafcetInFront(bool grafcetInFront)
{
    m_grafcetInFront = grafcetInFront;
    apply();
}

void DockContext::apply()
{
    untracked([this] {
        for (const Counterparts& pair : kCounterparts) {
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
