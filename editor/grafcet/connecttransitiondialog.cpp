#include "editor/grafcet/connecttransitiondialog.h"

#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>

#include <algorithm>

namespace editor {

namespace {

std::vector<int> ticked(const QListWidget* list)
{
    std::vector<int> numbers;
    for (int row = 0; row < list->count(); ++row) {
        const QListWidgetItem* item = list->item(row);
        if (item->checkState() == Qt::Checked)
            numbers.push_back(item->data(Qt::UserRole).toInt());
    }
    return numbers;
}

} // namespace

ConnectTransitionDialog::ConnectTransitionDialog(const core::Grafcet& grafcet, int transition,
                                                 const QString& grafcetName, QWidget* parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("connectTransitionDialog"));
    //: %1 the transition's number, %2 the GEMMA step whose GRAFCET it is in
    setWindowTitle(tr("Connect T%1 of %2").arg(transition).arg(grafcetName));
    const core::GrafcetTransition* t = grafcet.transition(transition);
    m_upstream = createList(grafcet, t ? t->upstream : std::vector<int>{}, QStringLiteral("upstreamList"));
    m_downstream = createList(grafcet, t ? t->downstream : std::vector<int>{}, QStringLiteral("downstreamList"));
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    m_reason = new QLabel(this);
    m_reason->setObjectName(QStringLiteral("reasonLabel"));
    m_reason->setWordWrap(true);

    auto* layout = new QGridLayout(this);
    layout->addWidget(new QLabel(tr("Upstream steps (it leaves them)"), this), 0, 0);
    layout->addWidget(new QLabel(tr("Downstream steps (it activates them)"), this), 0, 1);
    layout->addWidget(m_upstream, 1, 0);
    layout->addWidget(m_downstream, 1, 1);
    layout->addWidget(m_reason, 2, 0, 1, 2);
    layout->addWidget(m_buttons, 3, 0, 1, 2);
    updateOk();
}

QListWidget* ConnectTransitionDialog::createList(const core::Grafcet& grafcet, const std::vector<int>& current,
                                                 const QString& name)
{
    auto* list = new QListWidget(this);
    list->setObjectName(name);
    std::vector<int> order = current;
    for (const core::GrafcetStep& step : grafcet.steps())
        if (std::find(order.begin(), order.end(), step.number) == order.end())
            order.push_back(step.number);
    for (int number : order) {
        auto* item = new QListWidgetItem(tr("Step %1").arg(number), list);
        item->setData(Qt::UserRole, number);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        const bool linked = std::find(current.begin(), current.end(), number) != current.end();
        item->setCheckState(linked ? Qt::Checked : Qt::Unchecked);
    }
    connect(list, &QListWidget::itemChanged, this, &ConnectTransitionDialog::updateOk);
    return list;
}

std::vector<int> ConnectTransitionDialog::upstream() const
{
    return ticked(m_upstream);
}

std::vector<int> ConnectTransitionDialog::downstream() const
{
    return ticked(m_downstream);
}

void ConnectTransitionDialog::updateOk()
{
    if (!m_buttons || !m_reason)
        return;
    QString reason;
    if (upstream().empty())
        reason = tr("Tick an upstream step: a transition leaves at least one step.");
    else if (downstream().empty())
        reason = tr("Tick a downstream step: a transition activates at least one step. To end a branch on a "
                    "step with no transition after it, use Add Branch Ending on a Step on the step.");
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(reason.isEmpty());
    m_reason->setText(reason);
    m_reason->setVisible(!reason.isEmpty());
}

} // namespace editor
