#include "editor/docks/dockreveal.h"

#include <QDockWidget>
#include <QMainWindow>

namespace editor {

void revealDock(QDockWidget* dock)
{
    dock->show();
    dock->raise();
}

void raiseOverPropertySibling(QDockWidget* dock)
{
    auto* window = qobject_cast<QMainWindow*>(dock->parentWidget());
    if (!window || dock->isHidden() || !dock->visibleRegion().isEmpty())
        return;
    for (QDockWidget* sibling : window->tabifiedDockWidgets(dock)) {
        const QString name = sibling->objectName();
        if (name == QLatin1String("stepDock") || name == QLatin1String("transitionDock")
            || name == QLatin1String("grafcetStepDock") || name == QLatin1String("grafcetTransitionDock")) {
            dock->raise();
            return;
        }
    }
}

} // namespace editor
