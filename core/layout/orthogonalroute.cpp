#include "core/layout/orthogonalroute.h"

#include <algorithm>
#include <cmath>

namespace core {

namespace {

bool isHorizontalSide(Side side)
{
    return side == Side::Left || side == Side::Right;
}

} // namespace

Point anchorPoint(const Rect& box, Anchor anchor)
{
    const Point c = box.center();
    switch (anchor.side) {
    case Side::Left: return {box.left(), c.y + anchor.offset};
    case Side::Right: return {box.right(), c.y + anchor.offset};
    case Side::Top: return {c.x + anchor.offset, box.top()};
    case Side::Bottom: return {c.x + anchor.offset, box.bottom()};
    }
    return c;
}

std::vector<Point> orthogonalRoute(const Rect& source, Anchor exit, const std::vector<double>& turns,
                                   const Rect& target, Anchor entry)
{
    Point point = anchorPoint(source, exit);
    bool horizontal = isHorizontalSide(exit.side);
    std::vector<Point> route{point};
    for (double turn : turns) {
        (horizontal ? point.x : point.y) = turn;
        route.push_back(point);
        horizontal = !horizontal;
    }
    const Point end = anchorPoint(target, entry);
    if (horizontal != isHorizontalSide(entry.side)) {
        (horizontal ? point.x : point.y) = horizontal ? end.x : end.y;
        route.push_back(point);
    }
    route.push_back(end);
    return route;
}

Point pointAlong(Point from, Point to, double distance)
{
    const double length = std::abs(to.x - from.x) + std::abs(to.y - from.y);
    if (length <= 0)
        return from;
    if (distance < 0)
        distance += length;
    const double t = std::clamp(distance / length, 0.0, 1.0);
    return {from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t};
}

} // namespace core
