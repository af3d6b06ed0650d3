#pragma once

// Checks on orthogonal routes shared by the chart layout tests (GEMMA and
// PackML): their straight stretches, whether they enter a box, run on top
// of or cross each other.

#include "core/layout/geometry.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace routegeometry {

using core::Point;
using core::Rect;

struct Segment {
    Point a;
    Point b;
    std::string owner = {}; // what it belongs to, for messages ("link T3->5")

    bool vertical() const { return a.x == b.x; }
    bool horizontal() const { return a.y == b.y; }
    double length() const { return std::abs(b.x - a.x) + std::abs(b.y - a.y); }
};

inline std::vector<Segment> segmentsOf(const std::vector<Point>& route)
{
    std::vector<Segment> result;
    for (std::size_t i = 0; i + 1 < route.size(); ++i)
        result.push_back({route[i], route[i + 1]});
    return result;
}

inline std::string describe(Point p)
{
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

// Does an axis-aligned segment enter the interior of the rectangle?
inline bool segmentEnters(const Segment& s, const Rect& r)
{
    const double xMin = std::min(s.a.x, s.b.x);
    const double xMax = std::max(s.a.x, s.b.x);
    const double yMin = std::min(s.a.y, s.b.y);
    const double yMax = std::max(s.a.y, s.b.y);
    if (s.vertical())
        return xMin > r.left() && xMin < r.right() && yMin < r.bottom() && yMax > r.top();
    return yMin > r.top() && yMin < r.bottom() && xMin < r.right() && xMax > r.left();
}

inline bool onSegment(Point p, const Segment& s)
{
    if (s.vertical())
        return p.x == s.a.x && p.y >= std::min(s.a.y, s.b.y) && p.y <= std::max(s.a.y, s.b.y);
    return p.y == s.a.y && p.x >= std::min(s.a.x, s.b.x) && p.x <= std::max(s.a.x, s.b.x);
}

// Proper crossing of a horizontal and a vertical segment (not at an end).
inline bool crosses(const Segment& s, const Segment& t)
{
    if (s.vertical() == t.vertical())
        return false;
    const Segment& v = s.vertical() ? s : t;
    const Segment& h = s.vertical() ? t : s;
    const auto inside = [](double value, double p, double q) {
        return value > std::min(p, q) && value < std::max(p, q);
    };
    return inside(v.a.x, h.a.x, h.b.x) && inside(h.a.y, v.a.y, v.b.y);
}

// Length of the stretch two collinear segments share (0 when they do not).
inline double sharedLength(const Segment& s, const Segment& t)
{
    if (s.vertical() && t.vertical() && s.a.x == t.a.x) {
        const double lo = std::max(std::min(s.a.y, s.b.y), std::min(t.a.y, t.b.y));
        const double hi = std::min(std::max(s.a.y, s.b.y), std::max(t.a.y, t.b.y));
        return std::max(0.0, hi - lo);
    }
    if (s.horizontal() && t.horizontal() && s.a.y == t.a.y) {
        const double lo = std::max(std::min(s.a.x, s.b.x), std::min(t.a.x, t.b.x));
        const double hi = std::min(std::max(s.a.x, s.b.x), std::max(t.a.x, t.b.x));
        return std::max(0.0, hi - lo);
    }
    return 0;
}

inline bool onBorder(Point p, const Rect& r)
{
    const bool onVerticalSide = (p.x == r.left() || p.x == r.right()) && p.y >= r.top() && p.y <= r.bottom();
    const bool onHorizontalSide = (p.y == r.top() || p.y == r.bottom()) && p.x >= r.left() && p.x <= r.right();
    return onVerticalSide || onHorizontalSide;
}

inline double distance(Point p, const Rect& r)
{
    const double dx = std::max({r.left() - p.x, 0.0, p.x - r.right()});
    const double dy = std::max({r.top() - p.y, 0.0, p.y - r.bottom()});
    return std::hypot(dx, dy);
}

} // namespace routegeometry
