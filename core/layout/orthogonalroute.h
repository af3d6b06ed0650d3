#pragma once

#include "core/layout/geometry.h"

#include <vector>

namespace core {

// Orthogonal arrows between boxes, as the GEMMA and PackML charts draw them.

enum class Side { Left, Right, Top, Bottom };

// A point on a box side, offset from the middle of that side (rightwards on
// Top/Bottom, downwards on Left/Right).
struct Anchor {
    Side side;
    double offset = 0;
};

Point anchorPoint(const Rect& box, Anchor anchor);

// The route leaves the exit anchor perpendicular to its side, then bends at
// each coordinate of turns, alternately an x and a y; it adds the last bend
// needed to reach the entry anchor perpendicular to its side.
std::vector<Point> orthogonalRoute(const Rect& source, Anchor exit, const std::vector<double>& turns,
                                   const Rect& target, Anchor entry);

// The point `distance` along the straight stretch from `from` to `to`
// (negative: from `to`), clamped to the stretch.
Point pointAlong(Point from, Point to, double distance);

} // namespace core
