#pragma once

// Where the Machine tab draws each component: fixed cells, no dragging
// (the schematic is a view of the description, not a drawing of its own).
// A row per group: what moves (cylinders, conveyors, part sources), then
// what shows (lamps, delayed sensors), then the operator's panel (push
// buttons, selectors, emergency stops); a row wraps after kMaxColumns.

#include "core/machine/machine.h"

#include <QRectF>

#include <vector>

namespace editor::machinelayout {

inline constexpr double kCellWidth = 180;
inline constexpr double kGap = 14;
inline constexpr double kHeaderHeight = 34; // the name, then the kind
inline constexpr double kRoleLineHeight = 17;
inline constexpr double kPadding = 6;
inline constexpr int kMaxColumns = 5;

// The drawing's height inside a cell of the kind.
double bodyHeight(core::machine::ComponentKind kind);
double cellHeight(core::machine::ComponentKind kind);

// One rectangle per component, in Machine::components order, the first
// cell's corner at (0, 0); never overlapping.
std::vector<QRectF> placeComponents(const core::machine::Machine& machine);

} // namespace editor::machinelayout
