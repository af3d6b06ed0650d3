#include "editor/machine/machinelayout.h"

#include <algorithm>
#include <array>

namespace editor::machinelayout {

namespace {

using core::machine::ComponentKind;

int groupOf(ComponentKind kind)
{
    switch (kind) {
    case ComponentKind::DoubleActingCylinder:
    case ComponentKind::SingleActingCylinder:
    case ComponentKind::Conveyor:
    case ComponentKind::PartSource: return 0;
    case ComponentKind::Lamp:
    case ComponentKind::DelayedSensor: return 1;
    case ComponentKind::PushButton:
    case ComponentKind::Selector:
    case ComponentKind::EmergencyStop: return 2;
    }
    return 2;
}

constexpr int kGroups = 3;

} // namespace

double bodyHeight(ComponentKind kind)
{
    switch (kind) {
    case ComponentKind::DoubleActingCylinder:
    case ComponentKind::SingleActingCylinder: return 46;
    case ComponentKind::Conveyor: return 48;
    default: return 34;
    }
}

double cellHeight(ComponentKind kind)
{
    const auto roles = static_cast<double>(core::machine::kindSpec(kind).roles.size());
    return kHeaderHeight + bodyHeight(kind) + roles * kRoleLineHeight + 2 * kPadding;
}

std::vector<QRectF> placeComponents(const core::machine::Machine& machine)
{
    std::vector<QRectF> cells(machine.components.size());
    double top = 0;
    for (int group = 0; group < kGroups; ++group) {
        int column = 0;
        double rowHeight = 0;
        for (std::size_t i = 0; i < machine.components.size(); ++i) {
            const ComponentKind kind = machine.components[i].kind;
            if (groupOf(kind) != group)
                continue;
            if (column == kMaxColumns) {
                top += rowHeight + kGap;
                column = 0;
                rowHeight = 0;
            }
            cells[i] = QRectF(column * (kCellWidth + kGap), top, kCellWidth, cellHeight(kind));
            rowHeight = std::max(rowHeight, cellHeight(kind));
            ++column;
        }
        if (column > 0)
            top += rowHeight + kGap;
    }
    return cells;
}

} // namespace editor::machinelayout
