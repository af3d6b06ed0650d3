#include "core/formats/loaderror.h"

namespace core {

namespace {

std::string fileAndLocation(const std::string& file, const std::string& location)
{
    std::string text = file.empty() ? std::string("<input>") : file;
    text += ": ";
    if (!location.empty())
        text += location + ": ";
    return text;
}

} // namespace

std::string LoadError::toStringWithoutAdvice() const
{
    return fileAndLocation(file, location) + message;
}

std::string LoadError::toString() const
{
    return advice.empty() ? toStringWithoutAdvice() : toStringWithoutAdvice() + "; " + advice;
}

std::string LoadWarning::toString() const
{
    return fileAndLocation(file, location) + "warning: " + message;
}

} // namespace core
