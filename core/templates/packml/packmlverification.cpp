#include "core/templates/packml/packmlverification.h"

#include "core/templates/packml/packmlverifier.h"

namespace core::packml {

const VerificationEngines& verificationEngines()
{
    static const VerificationEngines engines{
        verifyPackmlModel,
    };
    return engines;
}

} // namespace core::packml
