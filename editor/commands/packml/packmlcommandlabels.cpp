#include "editor/commands/packml/packmlcommandlabels.h"

#include "editor/chart/packml/packmlcharttexts.h"
#include "editor/commands/modelcommand.h"

#include "core/templates/packml/packmlconfiguration.h"

#include <charconv>

namespace editor {

QString modeTitleOf(const core::Model& model, int number)
{
    const core::packml::Configuration* configuration = model.packml();
    const core::packml::Mode* mode = configuration ? configuration->mode(number) : nullptr;
    if (!mode || mode->displayName().empty())
        return QString::number(number);
    return PackmlChartTexts::modeTitle(number, toQString(mode->displayName()));
}

QString modeElement(int number)
{
    return QString::number(number);
}

int modeNumberOf(const std::string& element)
{
    int number = 0;
    std::from_chars(element.data(), element.data() + element.size(), number);
    return number;
}

} // namespace editor
