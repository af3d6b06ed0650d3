#include "core/templates/gemma/gemmaverification.h"

namespace core {

const VerificationEngines& gemmaVerificationEngines()
{
    static const VerificationEngines engines{
        checkGemmaProperty,
        verifyGemmaModel,
    };
    return engines;
}

} // namespace core
