#include "core/templates/packml/packmlengines.h"

#include "core/templates/packml/packmlchecks.h"
#include "core/templates/packml/packmlcodegen.h"
#include "core/templates/packml/packmlproperty.h"

namespace core::packml {

const TemplateEngines& engines()
{
    static const TemplateEngines engines{
        checkPackMLModel,
        checkPackmlProperty,
        buildPackmlPlcProject,
    };
    return engines;
}

} // namespace core::packml
