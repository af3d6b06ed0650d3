#include "editor/docks/gemma/startguide.h"

#include "editor/docks/wrappinglabel.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace editor {

StartGuide::StartGuide(QWidget* parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_text(new WrappingLabel(this))
    , m_exampleButton(new QPushButton(this))
    , m_userGuideButton(new QPushButton(this))
{
    setObjectName(QStringLiteral("startGuide"));
    m_title->setObjectName(QStringLiteral("startGuideTitle"));
    QFont titleFont = m_title->font();
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.25);
    m_title->setFont(titleFont);
    m_text->setObjectName(QStringLiteral("startGuideText"));
    m_text->setTextFormat(Qt::RichText);
    m_exampleButton->setObjectName(QStringLiteral("startGuideExample"));
    m_userGuideButton->setObjectName(QStringLiteral("startGuideUserGuide"));
    connect(m_exampleButton, &QPushButton::clicked, this, &StartGuide::exampleRequested);
    connect(m_userGuideButton, &QPushButton::clicked, this, &StartGuide::userGuideRequested);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_exampleButton);
    buttons->addWidget(m_userGuideButton);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(12, 10, 12, 10);
    layout->addWidget(m_title);
    layout->addWidget(m_text);
    layout->addLayout(buttons);
    layout->addStretch(1);
    retranslate();
}

void StartGuide::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void StartGuide::retranslate()
{
    m_title->setText(tr("Getting started"));
    const QString steps[] = {
        tr("<b>Hide</b> what your machine does not need: select states or transitions and press Delete "
           "(Shift+Delete shows them again)."),
        tr("<b>Declare</b> the buttons, sensors and actuators in the Variables panel below."),
        tr("<b>Write</b> each transition's condition: select the transition and press Enter. Red marks what "
           "is not finished yet."),
        tr("<b>Simulate</b> with F5, <b>verify</b> with F7, then export PLCopen XML for your PLC."),
    };
    QString list;
    for (const QString& step : steps)
        list += QStringLiteral("<li>%1</li>").arg(step);
    m_text->setText(QStringLiteral("<p>%1</p><ol style=\"margin-left: 14px; -qt-list-indent: 0;\">%2</ol><p>%3</p>")
                        .arg(tr("The chart is the GEMMA sheet: the ways your machine stops (A), works (F) and "
                                "fails (D), and the transitions between them."),
                             list, tr("Select a step or a transition to edit it here.")));
    m_exampleButton->setText(tr("Open an Example"));
    m_exampleButton->setToolTip(tr("A finished model to look at and simulate, opened as an untitled copy"));
    m_userGuideButton->setText(tr("User Guide"));
    m_userGuideButton->setToolTip(tr("How to build a model step by step (F1)"));
}

} // namespace editor
