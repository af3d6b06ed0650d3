#include "editor/machine/machinetab.h"

#include "editor/document.h"
#include "editor/machine/machineview.h"

#include <QTabBar>
#include <QTabWidget>

#include <algorithm>

namespace editor {

MachineTab::MachineTab(QTabWidget* tabs, Document* document, SimulationSession* session, QObject* parent)
    : QObject(parent)
    , m_tabs(tabs)
    , m_document(document)
    , m_session(session)
{
    connect(m_document, &Document::machineChanged, this, &MachineTab::sync);
    connect(m_document, &Document::modelReset, this, &MachineTab::sync);
    sync();
}

MachineTab::~MachineTab()
{
    delete m_view.data();
}

MachineView* MachineTab::view() const
{
    return m_view.data();
}

QString MachineTab::title()
{
    return tr("Machine");
}

void MachineTab::sync()
{
    const bool wanted = !m_document->model().machine().empty();
    if (wanted == !m_view.isNull())
        return;
    if (!wanted) {
        m_tabs->removeTab(m_tabs->indexOf(m_view));
        delete m_view.data();
        return;
    }
    m_view = new MachineView(m_document, m_session);
    connect(m_view, &MachineView::languageChanged, this, &MachineTab::retitle);
    // Right after the chart, before the GRAFCET tabs.
    const int index = m_tabs->insertTab(std::min(1, m_tabs->count()), m_view, title());
    for (QTabBar::ButtonPosition side : {QTabBar::LeftSide, QTabBar::RightSide}) {
        QWidget* close = m_tabs->tabBar()->tabButton(index, side);
        m_tabs->tabBar()->setTabButton(index, side, nullptr);
        delete close;
    }
    retitle();
}

void MachineTab::retitle()
{
    const int index = m_view ? m_tabs->indexOf(m_view) : -1;
    if (index < 0)
        return;
    m_tabs->setTabText(index, title());
    m_tabs->setTabToolTip(index, tr("The virtual machine: its components, moving as the simulation runs"));
}

} // namespace editor
