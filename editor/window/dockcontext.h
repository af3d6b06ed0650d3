#pragma once

#include "core/model/model.h"

#include <QObject>
#include <QStringList>

#include <utility>

class QDockWidget;
class QMainWindow;

namespace editor {

// The property docks follow the tab in front, as an IDE's tool windows
// follow the editor: Step and Transition while the GEMMA chart is in front,
// Nested Step and Nested Transition while a GRAFCET tab is. Five property
// docks tabbed together need ~470 px of tab bar, the column at 1366 x 768
// has ~340; three of them fit in every language. A dock the user closed
// (close button, View menu) stays closed in both contexts until the user
// shows it again; a dock hidden by the context is not "closed".
//
// The template is a context too: a GEMMA model has the Step, Transition and
// Simulation docks, a PackML model the State, Commands, Modes and PackML
// Simulation docks (State and Commands then give way to Nested Step and
// Nested Transition); a dock of the other template is hidden and left out
// of the View menu.
class DockContext : public QObject {
    Q_OBJECT
public:
    explicit DockContext(QMainWindow* window);

    // Follows the dock's user visibility from now on (the docks and their
    // deferred frames alike, by object name).
    void watch(QDockWidget* dock);
    void unwatch(QDockWidget* dock);

    // Shows the docks of the context, hides the other context's; the one
    // in front of the group gives its place to its counterpart.
    void setGrafcetInFront(bool grafcetInFront);
    bool grafcetInFront() const { return m_grafcetInFront; }
    void setTemplate(core::TemplateKind kind);
    core::TemplateKind templateKind() const { return m_template; }
    // Whether the dock (by object name) belongs to the other template.
    bool isForeign(const QString& objectName) const;
    void apply();

    // The docks (object names) the user closed, kept with the window state.
    QStringList closedDocks() const { return m_closed; }
    void setClosedDocks(const QStringList& names);

    // Runs `change` (restoring a layout, say) without taking the visibility
    // it sets for the user's.
    template <typename Change>
    void untracked(Change change)
    {
        const bool wasApplying = std::exchange(m_applying, true);
        change();
        m_applying = wasApplying;
    }

    static bool isContextDock(const QString& objectName);

private:
    bool eventFilter(QObject* watched, QEvent* event) override;
    QDockWidget* dockNamed(const QString& objectName) const;

    QMainWindow* m_window;
    QStringList m_closed;
    bool m_grafcetInFront = false;
    core::TemplateKind m_template = core::TemplateKind::Gemma;
    bool m_applying = false;
};

} // namespace editor
