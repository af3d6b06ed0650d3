#include "core/layout/geometry.h"

namespace core {

bool Rect::intersects(const Rect& other) const
{
    return left() < other.right() && other.left() < right()
        && top() < other.bottom() && other.top() < bottom();
}

bool Rect::contains(Point point) const
{
    return point.x >= left() && point.x <= right() && point.y >= top() && point.y <= bottom();
}

bool Rect::contains(const Rect& other) const
{
    return other.left() >= left() && other.right() <= right()
        && other.top() >= top() && other.bottom() <= bottom();
}

Rect Rect::adjusted(double margin) const
{
    return {x - margin, y - margin, width + 2 * margin, height + 2 * margin};
}

} // namespace core
