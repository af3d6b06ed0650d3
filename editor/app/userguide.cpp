#include "editor/app/userguide.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QEvent>
#include <QScrollBar>
#include <QStyle>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocumentFragment>
#include <QTextBrowser>
#include <QToolBar>
#include <QUrl>
#include <QVBoxLayout>

namespace editor {

namespace {

const QUrl& guideUrl()
{
    static const QUrl url(QStringLiteral("qrc:/docs/user-guide.md"));
    return url;
}

} // namespace

UserGuide::UserGuide(QWidget* parent)
    : QWidget(parent, Qt::Window)
    , m_browser(new QTextBrowser(this))
{
    setObjectName(QStringLiteral("userGuide"));
    m_browser->setObjectName(QStringLiteral("userGuideBrowser"));
    m_browser->setOpenExternalLinks(true); // web links go to the browser; the pages of docs/ stay here
    auto* bar = new QToolBar(this);
    QAction* back = bar->addAction(style()->standardIcon(QStyle::SP_ArrowBack), QString(), m_browser,
                                   &QTextBrowser::backward);
    back->setObjectName(QStringLiteral("guideBackAction"));
    back->setShortcut(QKeySequence::Back);
    QAction* forward = bar->addAction(style()->standardIcon(QStyle::SP_ArrowForward), QString(), m_browser,
                                      &QTextBrowser::forward);
    forward->setObjectName(QStringLiteral("guideForwardAction"));
    forward->setShortcut(QKeySequence::Forward);
    QAction* contents = bar->addAction(style()->standardIcon(QStyle::SP_DirHomeIcon), QString(), this,
                                       [this] { showTopic(Topic::GettingStarted); });
    contents->setObjectName(QStringLiteral("guideContentsAction"));
    connect(m_browser, &QTextBrowser::backwardAvailable, back, &QAction::setEnabled);
    connect(m_browser, &QTextBrowser::forwardAvailable, forward, &QAction::setEnabled);
    back->setEnabled(false);
    forward->setEnabled(false);
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(bar);
    layout->addWidget(m_browser);
    resize(820, 680);
    retranslate();
}

QString UserGuide::heading(Topic topic)
{
    switch (topic) {
    case Topic::GettingStarted: return QStringLiteral("Getting started");
    case Topic::Chart: return QStringLiteral("The chart");
    case Topic::StepPanel: return QStringLiteral("The Step panel");
    case Topic::TransitionPanel: return QStringLiteral("The Transition panel");
    case Topic::VariablesPanel: return QStringLiteral("The Variables panel");
    case Topic::ProblemsPanel: return QStringLiteral("The Problems panel");
    case Topic::StructuredTextPanel: return QStringLiteral("The Structured Text panel");
    case Topic::NestedGrafcets: return QStringLiteral("Nested GRAFCETs");
    case Topic::Simulation: return QStringLiteral("Simulation");
    case Topic::Verification: return QStringLiteral("Verification");
    case Topic::Export: return QStringLiteral("Export");
    case Topic::Keyboard: return QStringLiteral("Keyboard");
    case Topic::Packml: return QStringLiteral("PackML");
    }
    return {};
}

void UserGuide::showTopic(Topic topic)
{
    if (m_browser->source() != guideUrl()) {
        m_browser->setSource(guideUrl(), QTextDocument::MarkdownResource);
        fitPictures();
    }
    show();
    raise();
    activateWindow();
    const QString wanted = heading(topic);
    for (QTextBlock block = m_browser->document()->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() != 2 || block.text() != wanted)
            continue;
        m_browser->setTextCursor(QTextCursor(block));
        // The heading at the top of the view, not just somewhere visible.
        const QRectF bounds = m_browser->document()->documentLayout()->blockBoundingRect(block);
        m_browser->verticalScrollBar()->setValue(int(bounds.top()));
        m_currentHeading = wanted;
        return;
    }
    m_browser->verticalScrollBar()->setValue(0);
    m_currentHeading.clear();
}

// The screenshots are as wide as the screens they show: drawn at most the
// width of the text, the height following.
void UserGuide::fitPictures()
{
    constexpr double kPictureWidth = 760;
    for (QTextBlock block = m_browser->document()->begin(); block.isValid(); block = block.next()) {
        for (auto fragment = block.begin(); !fragment.atEnd(); ++fragment) {
            QTextCharFormat format = fragment.fragment().charFormat();
            if (!format.isImageFormat())
                continue;
            QTextImageFormat image = format.toImageFormat();
            image.setWidth(kPictureWidth);
            QTextCursor cursor(m_browser->document());
            cursor.setPosition(fragment.fragment().position());
            cursor.setPosition(fragment.fragment().position() + fragment.fragment().length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(image);
        }
    }
}

QString UserGuide::currentHeading() const
{
    return m_currentHeading;
}

void UserGuide::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void UserGuide::retranslate()
{
    setWindowTitle(tr("GG Studio User Guide"));
    for (QAction* action : findChildren<QAction*>()) {
        if (action->objectName() == QLatin1String("guideBackAction"))
            action->setText(tr("Back"));
        else if (action->objectName() == QLatin1String("guideForwardAction"))
            action->setText(tr("Forward"));
        else if (action->objectName() == QLatin1String("guideContentsAction"))
            action->setText(tr("Getting Started"));
    }
}

} // namespace editor
