#include "core/checks/checks.h"

#include "core/templates/templateengines.h"

namespace core {

std::vector<Diagnostic> checkModel(const Model& model)
{
    return enginesOf(model).checkModel(model);
}

} // namespace core
