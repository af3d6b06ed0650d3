#include "core/formats/loaderror.h"

namespace core {

std::string LoadError::toString() const
{
    std::string text = file.empty() ? std::string("<input>") : file;
    text += ": ";
    if (!location.empty())
        text += location + ": ";
    return text + message;
}

} // namespace core
