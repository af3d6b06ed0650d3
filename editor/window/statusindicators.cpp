#include "editor/window/statusindicators.h"

#include "editor/document.h"
#include "editor/style/severityicon.h"
#include "editor/text/diagnostictext.h"
#include "editor/verificationrunner.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QStyle>
#include <QToolButton>

#include <cmath>

namespace editor {

namespace {

QWidget* withoutMargins(QWidget* widget, QWidget* child)
{
    auto* layout = new QHBoxLayout(widget);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(child);
    return widget;
}

} // namespace

ProblemCounter::ProblemCounter(Document& document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_button(new QToolButton(this))
{
    setObjectName("problemCounter");
    m_button->setObjectName("problemCountButton");
    m_button->setAutoRaise(true);
    m_button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    m_button->setIconSize(QSize(iconSize, iconSize));
    withoutMargins(this, m_button);
    connect(m_button, &QToolButton::clicked, this, &ProblemCounter::clicked);
    connect(&document, &Document::diagnosticsChanged, this, &ProblemCounter::recount);
    connect(&document, &Document::modelReset, this, &ProblemCounter::recount);
    recount();
}

void ProblemCounter::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ProblemCounter::setVerification(const VerificationRunner* runner)
{
    m_verification = runner;
    for (auto signal : {&VerificationRunner::finished, &VerificationRunner::started})
        connect(runner, signal, this, &ProblemCounter::recount);
    connect(runner, &VerificationRunner::staleChanged, this, &ProblemCounter::recount);
    connect(runner, &VerificationRunner::resultCleared, this, &ProblemCounter::recount);
    recount();
}

void ProblemCounter::recount()
{
    m_errors = 0;
    m_warnings = 0;
    for (const core::Diagnostic& diagnostic : m_document.diagnostics()) {
        if (diagnostic.severity == core::Severity::Error)
            ++m_errors;
        else if (diagnostic.severity == core::Severity::Warning)
            ++m_warnings;
    }
    m_findings = 0;
    m_findingErrors = 0;
    m_findingsStale = false;
    if (m_verification && m_verification->hasResult()) {
        for (const core::VerificationFinding& finding : m_verification->result().findings) {
            ++m_findings;
            m_findingErrors += finding.severity == core::Severity::Error ? 1 : 0;
        }
        m_findingsStale = m_verification->isStale();
    }
    retranslate();
}

void ProblemCounter::retranslate()
{
    // The icon of the worst severity present; no icon when all is well.
    if (m_errors > 0 || m_findingErrors > 0)
        m_button->setIcon(severityIcon(core::Severity::Error));
    else if (m_warnings > 0 || m_findings > 0)
        m_button->setIcon(severityIcon(core::Severity::Warning));
    else
        m_button->setIcon(QIcon());

    QString text;
    if (m_errors == 0 && m_warnings == 0)
        text = tr("No problems");
    else
        text = tr("%n error(s)", nullptr, m_errors) + QStringLiteral(", ") +
               tr("%n warning(s)", nullptr, m_warnings);
    if (m_findings > 0) {
        //: the verification's findings after the checks' problems in the status bar
        text += QStringLiteral(" · ") + (m_findingsStale
                                             ? tr("Verification (outdated): %n finding(s)", nullptr, m_findings)
                                             : tr("Verification: %n finding(s)", nullptr, m_findings));
    }
    m_button->setText(text);
    m_button->setToolTip(tr("Show the Problems panel"));
}

ZoomIndicator::ZoomIndicator(QWidget* parent)
    : QWidget(parent)
    , m_label(new QLabel(this))
{
    setObjectName("zoomIndicator");
    m_label->setObjectName("zoomLabel");
    m_label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    // Wide enough for "Zoom: 800 %", so the status bar does not jump.
    m_label->setMinimumWidth(m_label->fontMetrics().horizontalAdvance(QStringLiteral("Zoom: 8888 %")));
    withoutMargins(this, m_label);
    retranslate();
}

void ZoomIndicator::setZoom(double zoom)
{
    m_zoom = zoom;
    retranslate();
}

QString ZoomIndicator::text() const
{
    return m_label->text();
}

void ZoomIndicator::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ZoomIndicator::retranslate()
{
    const int percent = int(std::lround(m_zoom * 100));
    m_label->setText(tr("Zoom: %1 %").arg(locale().toString(percent)));
    m_label->setToolTip(tr("The zoom of the tab in front. Ctrl+wheel or a pinch zooms about the mouse; "
                           "Ctrl+0 fits the drawing in the window, Ctrl+1 shows it at its actual size"));
}

StatusBadge::StatusBadge(QWidget* parent)
    : QLabel(parent)
{
    constexpr int kHorizontalPadding = 6;
    constexpr int kVerticalPadding = 1;
    setContentsMargins(kHorizontalPadding, kVerticalPadding, kHorizontalPadding, kVerticalPadding);
    QPalette colors = palette();
    colors.setColor(QPalette::WindowText, textColor());
    setPalette(colors);
}

void StatusBadge::paintEvent(QPaintEvent* event)
{
    constexpr double kCornerRadius = 3;
    {
        QPainter painter(this);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(Qt::NoPen);
        painter.setBrush(badgeColor());
        painter.drawRoundedRect(QRectF(rect()), kCornerRadius, kCornerRadius);
    }
    QLabel::paintEvent(event);
}

} // namespace editor
