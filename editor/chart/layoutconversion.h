#pragma once

#include "core/templates/gemma/gemmachartlayout.h"

#include <QPointF>
#include <QRectF>

namespace editor {

// core::ChartLayout geometry as Qt types (same units: scene units).
inline QPointF toQPointF(core::Point point)
{
    return {point.x, point.y};
}

inline QRectF toQRectF(const core::Rect& rect)
{
    return {rect.x, rect.y, rect.width, rect.height};
}

} // namespace editor
