#include "core/templates/gemma/gemmaengines.h"

#include "core/templates/gemma/gemmachecks.h"
#include "core/templates/gemma/gemmacodegen.h"

namespace core {

const TemplateEngines& gemmaEngines()
{
    static const TemplateEngines engines{
        checkGemmaModel,
        checkGemmaProperty,
        buildGemmaPlcProject,
    };
    return engines;
}

} // namespace core
