#include "editor/chart/packml/packmlchartview.h"

#include "core/templates/packml/packmlconfiguration.h"
#include "editor/chart/packml/packmlchartscene.h"
#include "editor/chart/packml/packmlcharttexts.h"
#include "editor/chart/packml/packmlsheetview.h"
#include "core/model/model.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace editor {

PackmlChartView::PackmlChartView(PackmlChartScene* scene, QWidget* parent)
    : QWidget(parent)
    , m_scene(scene)
    , m_modeLabel(new QLabel(this))
    , m_modes(new QComboBox(this))
    , m_sheet(new PackmlSheetView(scene, this))
{
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(6, 4, 6, 4);
    bar->addWidget(m_modeLabel);
    bar->addWidget(m_modes);
    bar->addStretch(1);
    m_modeLabel->setBuddy(m_modes);
    m_modes->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(bar);
    layout->addWidget(m_sheet, 1);
    setFocusProxy(m_sheet);
    retranslate();
    fillModes();

    connect(m_modes, &QComboBox::activated, this, [this](int index) { m_scene->setMode(m_modes->itemData(index).toInt()); });
    connect(m_scene, &PackmlChartScene::modesChanged, this, &PackmlChartView::fillModes);
    connect(m_scene, &PackmlChartScene::modeChanged, this, &PackmlChartView::showSceneMode);
    connect(m_scene, &PackmlChartScene::stateDoubleClicked, this, &PackmlChartView::stateDoubleClicked);
}

void PackmlChartView::fillModes()
{
    const QSignalBlocker blocker(m_modes);
    m_modes->clear();
    if (const core::packml::Configuration* configuration = m_scene->model().packml()) {
        for (const core::packml::Mode& mode : configuration->modes) {
            const std::string_view name = mode.displayName();
            m_modes->addItem(PackmlChartTexts::modeTitle(mode.number, QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()))),
                             mode.number);
        }
    }
    m_modes->setEnabled(m_modes->count() > 0);
    showSceneMode(m_scene->mode());
}

void PackmlChartView::showSceneMode(int mode)
{
    const QSignalBlocker blocker(m_modes);
    m_modes->setCurrentIndex(m_modes->findData(mode));
}

void PackmlChartView::retranslate()
{
    m_modeLabel->setText(tr("Unit &mode:"));
    m_modes->setToolTip(tr("The unit mode the chart shows: its disabled states greyed, its skipped transitions "
                           "labelled with where they lead"));
}

void PackmlChartView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        m_scene->retranslate();
    }
    QWidget::changeEvent(event);
}

} // namespace editor
