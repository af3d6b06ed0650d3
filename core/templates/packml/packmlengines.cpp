#include "core/templates/packml/packmlengines.h"

#include "core/templates/packml/packmlchecks.h"
#include "core/templates/packml/packmlcodegen.h"

namespace core::packml {

const TemplateEngines& engines()
{
    static const TemplateEngines engines{
        checkPackMLModel,
        buildPackmlPlcProject,
    };
    return engines;
}

} // namespace core::packml
