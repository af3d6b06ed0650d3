#include "core/templates/packml/packmlverification.h"

#include "core/templates/packml/packmlproperty.h"
#include "core/templates/packml/packmlverifier.h"

namespace core::packml {

const VerificationEngines& verificationEngines()
{
    static const VerificationEngines engines{
        checkPackmlProperty,
        verifyPackmlModel,
    };
    return engines;
}

} // namespace core::packml
