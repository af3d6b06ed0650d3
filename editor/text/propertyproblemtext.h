#pragma once

#include <QString>

namespace core {
struct PropertyProblem;
}

namespace editor {

// What is wrong with a verification property, in the UI language.
QString propertyProblemText(const core::PropertyProblem& problem);

} // namespace editor
