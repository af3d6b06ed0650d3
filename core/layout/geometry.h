#pragma once

namespace core {

// Plane geometry of the charts' layouts (GEMMA, PackML, GRAFCET), in scene
// units with y growing downwards.

struct Point {
    double x = 0;
    double y = 0;

    friend bool operator==(const Point&, const Point&) = default;
};

struct Rect {
    double x = 0;
    double y = 0;
    double width = 0;
    double height = 0;

    double left() const { return x; }
    double top() const { return y; }
    double right() const { return x + width; }
    double bottom() const { return y + height; }
    Point center() const { return {x + width / 2, y + height / 2}; }

    // Interiors overlap; rectangles that only touch along an edge do not.
    bool intersects(const Rect& other) const;
    // Border included.
    bool contains(Point point) const;
    bool contains(const Rect& other) const;
    // Grown by margin on every side (shrunk when margin is negative).
    Rect adjusted(double margin) const;

    friend bool operator==(const Rect&, const Rect&) = default;
};

} // namespace core
