#pragma once

#include "editor/simulation/grafcetsimulationmarks.h"

#include <string>

namespace editor {

class GrafcetScene;
class PackmlSimulationSession;

// The PackML simulation on the tab of a nested GRAFCET (the scene's key is
// core::packml::grafcetKey(mode, state)), drawn by GrafcetSimulationMarks as
// for GEMMA. Several instances may run one GRAFCET (a mode "same as"
// another): the tab shows the instance of the current (mode, state) when it
// runs this GRAFCET, else the owner mode's own instance, greyed as it was
// left. Its caption names the instance ("Production_Execute is active...").

// What the marks show of the GRAFCET of `key` in the scan the session shows.
GrafcetSimulationSnapshot packmlGrafcetSnapshot(const PackmlSimulationSession& session, const std::string& key);

// Marks on `scene`, updated with the session's scans and history; owned by `parent`.
GrafcetSimulationMarks* addPackmlGrafcetMarks(PackmlSimulationSession* session, GrafcetScene* scene, QObject* parent);

} // namespace editor
