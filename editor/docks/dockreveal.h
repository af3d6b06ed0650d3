#pragma once

class QDockWidget;

namespace editor {

// Shows a dock and brings its tab to the front, for a request to focus one
// of its fields.
void revealDock(QDockWidget* dock);

// The Step and Transition docks and their nested GRAFCET counterparts show
// one selection kind each; when they
// share a tab group, the one that has something to show comes to the front
// as the selection changes kind.
void raiseOverPropertySibling(QDockWidget* dock);

} // namespace editor
