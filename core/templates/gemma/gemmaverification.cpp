#include "core/templates/gemma/gemmaverification.h"

namespace core {

const VerificationEngines& gemmaVerificationEngines()
{
    static const VerificationEngines engines{
        verifyGemmaModel,
    };
    return engines;
}

} // namespace core
