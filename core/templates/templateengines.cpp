#include "core/templates/templateengines.h"

#include "core/model/model.h"
#include "core/templates/gemma/gemmaengines.h"
#include "core/templates/packml/packmlengines.h"

namespace core {

const TemplateEngines& enginesOf(const Model& model)
{
    switch (model.templateKind()) {
    case TemplateKind::PackML: return packml::engines();
    case TemplateKind::Gemma: break;
    }
    return gemmaEngines();
}

} // namespace core
