#include "core/templates/templateverification.h"

#include "core/model/model.h"
#include "core/templates/gemma/gemmaverification.h"
#include "core/templates/packml/packmlverification.h"

namespace core {

const VerificationEngines& verificationEnginesOf(const Model& model)
{
    switch (model.templateKind()) {
    case TemplateKind::PackML: return packml::verificationEngines();
    case TemplateKind::Gemma: break;
    }
    return gemmaVerificationEngines();
}

} // namespace core
