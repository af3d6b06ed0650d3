#include "editor/docks/diagnosticlist.h"

#include "editor/docks/declarationfix.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/style/severityicon.h"
#include "editor/text/diagnostictext.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

namespace editor {

DiagnosticList::DiagnosticList(QWidget* parent)
    : QWidget(parent)
    , m_layout(new QVBoxLayout(this))
{
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(2);
    setVisible(false);
}

void DiagnosticList::setDiagnostics(const std::vector<core::Diagnostic>& diagnostics)
{
    if (diagnostics == m_diagnostics)
        return; // no flicker while typing leaves the problems as they are
    m_diagnostics = diagnostics;
    rebuildRows();
}

void DiagnosticList::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        rebuildRows(); // the messages are worded when the rows are built
    QWidget::changeEvent(event);
}

void DiagnosticList::rebuildRows()
{
    while (QLayoutItem* item = m_layout->takeAt(0)) {
        delete item->widget(); // a row and its labels
        delete item;
    }
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    for (const core::Diagnostic& diagnostic : m_diagnostics) {
        auto* rowWidget = new QWidget(this);
        auto* row = new QHBoxLayout(rowWidget);
        row->setContentsMargins(0, 0, 0, 0);
        row->setSpacing(4);
        auto* icon = new QLabel(rowWidget);
        icon->setPixmap(severityIcon(diagnostic.severity).pixmap(iconSize, iconSize));
        icon->setAlignment(Qt::AlignTop);
        icon->setToolTip(severityText(diagnostic.severity));
        auto* text = new WrappingLabel(diagnosticText(diagnostic), rowWidget);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        text->setToolTip(QString::fromStdString(diagnostic.code));
        row->addWidget(icon, 0, Qt::AlignTop);
        row->addWidget(text, 1);
        m_layout->addWidget(rowWidget);
        addFixButton(diagnostic);
    }
    setVisible(!m_diagnostics.empty());
}

void DiagnosticList::addFixButton(const core::Diagnostic& diagnostic)
{
    const std::optional<DeclarationFix> fix
        = m_document ? DeclarationFix::of(m_document->model(), diagnostic) : std::nullopt;
    if (!fix)
        return;
    auto* button = new QToolButton(this);
    button->setObjectName(QStringLiteral("declareVariableButton"));
    button->setText(fix->text());
    button->setAutoRaise(true);
    button->setEnabled(!m_document->isReadOnly());
    // Queued: the declaration changes the problems, and so these rows, the
    // button among them.
    connect(
        button, &QToolButton::clicked, this, [this, declaration = *fix] { declaration.apply(*m_document); },
        Qt::QueuedConnection);
    m_layout->addWidget(button, 0, Qt::AlignLeft);
}

} // namespace editor
