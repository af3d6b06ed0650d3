// Writes the template chart layout as an SVG to look at it, and prints a few
// quality figures (route crossings, labels lying on routes) to stderr.
// Usage: dump_layout_svg [output.svg]   (stdout when no file is given)

#include "core/templates/gemma/gemmachartlayout.h"
#include "core/templates/gemma/gemmatemplate.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace core;

namespace {

std::string frameTitle(Family family)
{
    switch (family) {
    case Family::A: return "A  Stop procedures";
    case Family::F: return "F  Operation procedures";
    case Family::D: return "D  Failure procedures";
    }
    return "?";
}

void writeRect(std::ostream& out, const Rect& r, const char* style)
{
    out << "<rect x='" << r.x << "' y='" << r.y << "' width='" << r.width << "' height='" << r.height
        << "' style='" << style << "'/>\n";
}

void writeLine(std::ostream& out, Point a, Point b, const char* style)
{
    out << "<line x1='" << a.x << "' y1='" << a.y << "' x2='" << b.x << "' y2='" << b.y << "' style='" << style
        << "'/>\n";
}

void writeText(std::ostream& out, Point at, const std::string& text, int size, const char* extra = "")
{
    out << "<text x='" << at.x << "' y='" << at.y << "' font-family='sans-serif' font-size='" << size << "' " << extra
        << ">" << text << "</text>\n";
}

void writeStep(std::ostream& out, const StepLayout& step)
{
    const TemplateState* state = findTemplateState(step.id);
    const Rect& box = step.box;
    const double inset = 4;
    const Rect symbol = box.adjusted(-inset);
    writeRect(out, symbol, "fill:white;stroke:black;stroke-width:1.5");
    if (state && state->defaultInitial)
        writeRect(out, symbol.adjusted(-4), "fill:none;stroke:black;stroke-width:1.2");
    if (state && state->defaultType == StepType::Macro) {
        writeLine(out, {symbol.left(), symbol.top() + 4}, {symbol.right(), symbol.top() + 4}, "stroke:black");
        writeLine(out, {symbol.left(), symbol.bottom() - 4}, {symbol.right(), symbol.bottom() - 4}, "stroke:black");
    }
    if (state && state->defaultType == StepType::Enclosing) {
        writeLine(out, {symbol.left() + 4, symbol.top()}, {symbol.left() + 4, symbol.bottom()}, "stroke:black");
        writeLine(out, {symbol.right() - 4, symbol.top()}, {symbol.right() - 4, symbol.bottom()}, "stroke:black");
    }
    writeRect(out, box, "fill:none;stroke:#c0c0ff;stroke-width:0.5;stroke-dasharray:2,2");
    const Point c = box.center();
    writeText(out, {c.x, c.y + 5}, std::string(step.id), 14, "text-anchor='middle' font-weight='bold'");
}

void writeArrowHead(std::ostream& out, Point from, Point tip)
{
    const double dx = tip.x > from.x ? 1 : tip.x < from.x ? -1 : 0;
    const double dy = tip.y > from.y ? 1 : tip.y < from.y ? -1 : 0;
    const double len = 8;
    const double half = 4;
    const Point base{tip.x - dx * len, tip.y - dy * len};
    out << "<polygon points='" << tip.x << "," << tip.y << " " << base.x - dy * half << "," << base.y - dx * half << " "
        << base.x + dy * half << "," << base.y + dx * half << "' style='fill:black'/>\n";
}

void writeTransition(std::ostream& out, const TransitionLayout& t, int priority)
{
    out << "<polyline points='";
    for (const Point& p : t.route)
        out << p.x << "," << p.y << " ";
    out << "' style='fill:none;stroke:#333;stroke-width:1.2'/>\n";
    writeArrowHead(out, t.route[t.route.size() - 2], t.route.back());
    const double half = kTransitionBarLength / 2;
    const Point c = t.barCenter;
    if (t.barHorizontal)
        writeLine(out, {c.x - half, c.y}, {c.x + half, c.y}, "stroke:black;stroke-width:3");
    else
        writeLine(out, {c.x, c.y - half}, {c.x, c.y + half}, "stroke:black;stroke-width:3");
    writeRect(out, t.labelRect, "fill:#fff8d0;fill-opacity:0.8;stroke:#d0b040;stroke-width:0.5");
    // Text placed like the editor does: towards the bar.
    const Rect& r = t.labelRect;
    const std::string text = std::to_string(priority) + ": " + t.id;
    if (r.right() <= c.x + 0.5)
        writeText(out, {r.right() - 3, r.y + 12}, text, 11, "text-anchor='end'");
    else if (r.left() >= c.x - 0.5)
        writeText(out, {r.x + 3, r.y + 12}, text, 11);
    else
        writeText(out, {r.center().x, r.y + 12}, text, 11, "text-anchor='middle'");
}

// Figures to watch while tuning the table by eye.
struct Segment {
    Point a;
    Point b;
};

bool segmentsCross(const Segment& s, const Segment& t)
{
    const bool sv = s.a.x == s.b.x;
    const bool tv = t.a.x == t.b.x;
    if (sv == tv)
        return false;
    const Segment& v = sv ? s : t;
    const Segment& h = sv ? t : s;
    const double x = v.a.x;
    const double y = h.a.y;
    const auto strictlyBetween = [](double value, double p, double q) {
        return value > std::min(p, q) && value < std::max(p, q);
    };
    return strictlyBetween(x, h.a.x, h.b.x) && strictlyBetween(y, v.a.y, v.b.y);
}

bool segmentHitsRect(const Segment& s, const Rect& r)
{
    const double xMin = std::min(s.a.x, s.b.x);
    const double xMax = std::max(s.a.x, s.b.x);
    const double yMin = std::min(s.a.y, s.b.y);
    const double yMax = std::max(s.a.y, s.b.y);
    if (xMin == xMax)
        return xMin > r.left() && xMin < r.right() && yMin < r.bottom() && yMax > r.top();
    return yMin > r.top() && yMin < r.bottom() && xMin < r.right() && xMax > r.left();
}

void printFigures(const ChartLayout& layout)
{
    int crossings = 0;
    for (std::size_t i = 0; i < layout.transitions.size(); ++i) {
        for (std::size_t j = i + 1; j < layout.transitions.size(); ++j) {
            const auto& a = layout.transitions[i].route;
            const auto& b = layout.transitions[j].route;
            for (std::size_t p = 0; p + 1 < a.size(); ++p) {
                for (std::size_t q = 0; q + 1 < b.size(); ++q) {
                    if (segmentsCross({a[p], a[p + 1]}, {b[q], b[q + 1]})) {
                        ++crossings;
                        std::cerr << "crossing: " << layout.transitions[i].id << " x " << layout.transitions[j].id
                                  << "\n";
                    }
                }
            }
        }
    }
    int labelsOnRoutes = 0;
    for (const TransitionLayout& label : layout.transitions) {
        for (const TransitionLayout& other : layout.transitions) {
            if (&other == &label)
                continue;
            for (std::size_t p = 0; p + 1 < other.route.size(); ++p) {
                if (segmentHitsRect({other.route[p], other.route[p + 1]}, label.labelRect)) {
                    ++labelsOnRoutes;
                    std::cerr << "label of " << label.id << " lies on route " << other.id << "\n";
                    break;
                }
            }
        }
    }
    std::cerr << crossings << " crossings, " << labelsOnRoutes << " labels on other routes\n";
}

Rect barRect(const TransitionLayout& t)
{
    const double half = kTransitionBarLength / 2;
    if (t.barHorizontal)
        return {t.barCenter.x - half, t.barCenter.y - 1, kTransitionBarLength, 2};
    return {t.barCenter.x - 1, t.barCenter.y - half, 2, kTransitionBarLength};
}

bool labelFits(const ChartLayout& layout, const TransitionLayout& t, const Rect& label)
{
    bool inFrame = false;
    for (const FrameLayout& frame : layout.frames) {
        if (label.intersects(frame.titleRect))
            return false;
        inFrame = inFrame || frame.rect.contains(label);
    }
    if (!inFrame)
        return false;
    for (const StepLayout& step : layout.steps) {
        if (label.intersects(step.box))
            return false;
    }
    for (const TransitionLayout& other : layout.transitions) {
        if (label.intersects(barRect(other)))
            return false;
        if (&other != &t && label.intersects(other.labelRect))
            return false;
        for (std::size_t p = 0; p + 1 < other.route.size(); ++p) {
            if (segmentHitsRect({other.route[p], other.route[p + 1]}, label))
                return false;
        }
    }
    return true;
}

// How wide each label could grow, its side towards the bar kept in place
// (both sides when it is centred on the bar): the room left for tuning.
void printLabelRoom(const ChartLayout& layout)
{
    for (const TransitionLayout& t : layout.transitions) {
        const Rect& r = t.labelRect;
        double room = r.width;
        for (double width = r.width + 1; width <= 400; ++width) {
            Rect grown = r;
            grown.width = width;
            if (r.right() <= t.barCenter.x + 0.5)
                grown.x = r.right() - width;
            else if (r.left() < t.barCenter.x - 0.5)
                grown.x = r.center().x - width / 2;
            if (!labelFits(layout, t, grown))
                break;
            room = width;
        }
        std::cerr << "label " << t.id << ": " << r.width << " wide, room for " << room << "\n";
    }
}

} // namespace

int main(int argc, char** argv)
{
    const ChartLayout& layout = templateLayout();
    std::ostringstream svg;
    const Rect& scene = layout.sceneRect;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' viewBox='" << scene.x << " " << scene.y << " " << scene.width
        << " " << scene.height << "' width='" << scene.width << "' height='" << scene.height << "'>\n";
    writeRect(svg, scene, "fill:white;stroke:none");
    for (const FrameLayout& frame : layout.frames) {
        writeRect(svg, frame.rect, "fill:#f4f7fb;stroke:#406080;stroke-width:2");
        writeRect(svg, frame.titleRect, "fill:none;stroke:#a0b0c0;stroke-width:0.5");
        writeText(svg, {frame.titleRect.x + 4, frame.titleRect.y + 15}, frameTitle(frame.family), 15,
                  "font-weight='bold' fill='#204060'");
    }
    for (const TransitionLayout& t : layout.transitions) {
        int priority = 1;
        for (const TemplateTransition& tt : templateTransitions()) {
            if (makeTransitionId(tt.source, tt.target) == t.id)
                priority = tt.defaultPriority;
        }
        writeTransition(svg, t, priority);
    }
    for (const StepLayout& step : layout.steps)
        writeStep(svg, step);
    svg << "</svg>\n";

    printFigures(layout);
    printLabelRoom(layout);
    if (argc > 1) {
        std::ofstream file(argv[1]);
        file << svg.str();
        if (!file) {
            std::cerr << "cannot write " << argv[1] << "\n";
            return 1;
        }
        return 0;
    }
    std::cout << svg.str();
    return 0;
}
