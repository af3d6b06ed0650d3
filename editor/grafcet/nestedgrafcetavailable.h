#pragma once

#include "core/model/model.h"

#include <QString>

namespace editor {

// Whether the GEMMA step's GRAFCET tab can open: it has a GRAFCET, or it is
// a macro-step or an enclosing step that may get one (its tab then offers
// to create the usual shape).
inline bool canOpenNestedGrafcet(const core::Model& model, const QString& stepId)
{
    const std::string id = stepId.toStdString();
    const core::Step* step = model.step(id);
    return model.grafcet(id) || (step && core::hasNestedBehaviour(step->type));
}

} // namespace editor
