#include "editor/chart/packml/packmlchartbinding.h"

#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlchartview.h"
#include "editor/document.h"

#include "core/templates/packml/packmlconfiguration.h"

namespace editor {

PackmlChartBinding::PackmlChartBinding(Document* document, PackmlChartView* view, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_view(view)
{
    PackmlChartScene* scene = view->chartScene();
    for (auto signal : {&Document::modelReset, &Document::packmlSettingsChanged, &Document::modesChanged})
        connect(document, signal, scene, &PackmlChartScene::refresh);
    connect(document, &Document::modeChanged, scene, &PackmlChartScene::refresh);
    connect(view, &PackmlChartView::stateDoubleClicked, this, &PackmlChartBinding::onStateDoubleClicked);
}

QString PackmlChartBinding::runningGrafcet(const Document& document, int modeNumber, const QString& stateName)
{
    const core::packml::Configuration* configuration = document.model().packml();
    const auto state = core::packml::findState(stateName.toStdString());
    if (!configuration || !state || !core::packml::holdsGrafcet(*state))
        return {};
    const core::packml::Mode* mode = configuration->mode(modeNumber);
    if (!mode)
        return {};
    const core::packml::GrafcetChoice& choice = mode->grafcetChoice(*state);
    int owner = 0;
    if (choice.kind == core::packml::GrafcetChoice::Kind::Own)
        owner = mode->number;
    else if (choice.kind == core::packml::GrafcetChoice::Kind::SameAs)
        owner = choice.sameAsMode;
    const std::string key = core::packml::grafcetKey(owner, *state);
    if (owner == 0 || !document.model().grafcet(key))
        return {};
    return QString::fromStdString(key);
}

void PackmlChartBinding::onStateDoubleClicked(int mode, const QString& state)
{
    const QString key = runningGrafcet(*m_document, mode, state);
    if (!key.isEmpty())
        emit openGrafcetRequested(key);
}

} // namespace editor
