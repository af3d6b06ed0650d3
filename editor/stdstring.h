#pragma once

#include <QString>

#include <string>

namespace editor {

// The core library speaks UTF-8 std::string; the widgets speak QString.
inline QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

} // namespace editor
