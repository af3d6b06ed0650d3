// Writes the PackML chart layout as an SVG to look at it.
// Usage: dump_packml_chart_svg 2015|2022 [holdInSuspended] [completeInSuspendedHeld] > chart.svg
// (the edition's default options, plus those named)

#include "core/templates/packml/packmlchartlayout.h"
#include "core/templates/packml/packmltemplate.h"

#include <iostream>
#include <string>
#include <string_view>

using namespace core;
using namespace core::packml;

namespace {

void writeRect(std::ostream& out, const Rect& r, std::string_view style)
{
    out << "<rect x='" << r.x << "' y='" << r.y << "' width='" << r.width << "' height='" << r.height
        << "' style='" << style << "'/>\n";
}

void writeText(std::ostream& out, Point at, std::string_view text, int size, std::string_view extra = "")
{
    out << "<text x='" << at.x << "' y='" << at.y << "' font-family='sans-serif' font-size='" << size << "' "
        << extra << ">" << text << "</text>\n";
}

void writeArrowHead(std::ostream& out, Point from, Point tip)
{
    const double dx = tip.x > from.x ? 1 : tip.x < from.x ? -1 : 0;
    const double dy = tip.y > from.y ? 1 : tip.y < from.y ? -1 : 0;
    const Point base{tip.x - dx * 9, tip.y - dy * 9};
    out << "<polygon points='" << tip.x << "," << tip.y << " " << base.x - dy * 4 << "," << base.y - dx * 4 << " "
        << base.x + dy * 4 << "," << base.y + dx * 4 << "' style='fill:black'/>\n";
}

// A label left of its bar ends at the bar, as the GUI writes it.
void writeArrow(std::ostream& out, const ChartArrow& arrow, std::string_view label, bool dashed)
{
    out << "<polyline fill='none' stroke='black' stroke-width='1.3'" << (dashed ? " stroke-dasharray='6,4'" : "")
        << " points='";
    for (Point p : arrow.route)
        out << p.x << "," << p.y << " ";
    out << "'/>\n";
    writeArrowHead(out, arrow.route[arrow.route.size() - 2], arrow.route.back());
    const double half = kChartBarLength / 2;
    const Point c = arrow.barCenter;
    const Rect bar = arrow.barHorizontal ? Rect{c.x - half, c.y - 1.5, kChartBarLength, 3}
                                         : Rect{c.x - 1.5, c.y - half, 3, kChartBarLength};
    writeRect(out, bar, "fill:black");
    const Rect& r = arrow.labelRect;
    writeRect(out, r, "fill:none;stroke:#d0a0a0;stroke-width:0.5");
    if (r.right() < arrow.barCenter.x)
        writeText(out, {r.right() - 2, r.bottom() - 4}, label, 11, "text-anchor='end'");
    else
        writeText(out, {r.center().x, r.bottom() - 4}, label, 11, "text-anchor='middle'");
}

std::string_view fill(State state)
{
    switch (stateInfo(state).kind) {
    case StateKind::Wait: return "#a0f0f0";
    case StateKind::Acting: return "#a8e6a0";
    case StateKind::Dual: return "white";
    }
    return "white";
}

} // namespace

int main(int argc, char** argv)
{
    Options options = defaultOptions(argc > 1 && std::string_view(argv[1]) == "2022" ? Edition::Y2022 : Edition::Y2015);
    for (int i = 2; i < argc; ++i) {
        options.holdInSuspended = options.holdInSuspended || std::string_view(argv[i]) == "holdInSuspended";
        options.completeInSuspendedHeld
            = options.completeInSuspendedHeld || std::string_view(argv[i]) == "completeInSuspendedHeld";
    }
    const PackmlChartLayout layout = chartLayout(options);
    std::ostream& out = std::cout;
    const Rect& scene = layout.sceneRect;
    out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << scene.width << "' height='" << scene.height
        << "'>\n";
    writeRect(out, scene, "fill:white");
    for (const ChartFrame& frame : layout.frames) {
        writeRect(out, frame.rect, "fill:none;stroke:#606060;stroke-width:1.5");
        writeText(out, {frame.titleRect.x, frame.titleRect.bottom() - 4}, commandName(frame.command), 13,
                  "font-weight='bold'");
        writeArrow(out, frame.arrow, commandName(frame.command), false);
    }
    for (const ChartStateBox& box : layout.states) {
        writeRect(out, box.box, std::string("stroke:black;stroke-width:1.3;fill:") + std::string(fill(box.state)));
        const Point c = box.box.center();
        writeText(out, {c.x, c.y + 5}, stateName(box.state), 13, "text-anchor='middle'");
    }
    for (const ChartTransition& t : layout.transitions) {
        const std::string_view label
            = t.transition.trigger == Trigger::StateComplete ? "SC" : commandName(t.transition.command);
        writeArrow(out, t.arrow, label, t.transition.optional);
    }
    out << "</svg>\n";
}
