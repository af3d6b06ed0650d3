#include "editor/docks/propertydock.h"

#include "editor/docks/dockreveal.h"
#include "editor/docks/wrappinglabel.h"
#include "editor/document.h"
#include "editor/selection.h"
#include "editor/style/secondarytext.h"

#include "core/model/model.h"

#include <QEvent>
#include <QLabel>
#include <QScrollArea>
#include <QStackedWidget>

namespace editor {

PropertyDock::PropertyDock(ElementRef::Kind kind, const QString& title, Document* document, Selection* selection,
                           QWidget* parent)
    : QDockWidget(title, parent)
    , m_kind(kind)
    , m_document(document)
    , m_selection(selection)
{
}

void PropertyDock::setPages(QWidget* form)
{
    m_pages = new QStackedWidget(this);
    m_placeholder = new WrappingLabel(m_pages);
    m_placeholder->setObjectName(QStringLiteral("placeholder"));
    m_placeholder->setAlignment(Qt::AlignCenter);
    useSecondaryText(m_placeholder); // read, not greyed out as disabled text would be
    m_placeholder->setMargin(12);
    m_pages->addWidget(m_placeholder);
    m_pages->addWidget(form);
    setWidget(m_pages);

    connect(m_document, &Document::stepChanged, this, &PropertyDock::refresh);
    connect(m_document, &Document::transitionChanged, this, &PropertyDock::refresh);
    connect(m_document, &Document::modelReset, this, &PropertyDock::refresh);
    connect(m_document, &Document::grafcetChanged, this, &PropertyDock::refresh);
    connect(m_document, &Document::diagnosticsChanged, this, &PropertyDock::refresh);
    connect(m_selection, &Selection::changed, this, &PropertyDock::onSelectionChanged);
    connect(m_selection, &Selection::focusFieldRequested, this, &PropertyDock::onFocusFieldRequested);
    onSelectionChanged(m_selection->current());
}

QScrollArea* PropertyDock::scrolling(QWidget* content)
{
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    return scroll;
}

void PropertyDock::refreshOnVariableChanges()
{
    connect(m_document, &Document::variableChanged, this, &PropertyDock::refresh);
    connect(m_document, &Document::variablesChanged, this, &PropertyDock::refresh);
}

void PropertyDock::setPlaceholder(const QString& text)
{
    m_placeholder->setText(text);
}

void PropertyDock::setIdlePage(QWidget* page)
{
    m_idlePage = page;
    m_pages->addWidget(page);
    refresh();
}

void PropertyDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange && m_pages) {
        retranslate();
        refresh();
    }
    QDockWidget::changeEvent(event);
}

void PropertyDock::refresh()
{
    const bool shown = exists(element());
    if (shown)
        m_pages->setCurrentIndex(1);
    else if (m_idlePage && m_selection->current().isNull())
        m_pages->setCurrentWidget(m_idlePage);
    else
        m_pages->setCurrentWidget(m_placeholder);
    if (shown)
        refreshForm();
}

bool PropertyDock::exists(const ElementRef& element) const
{
    const core::Model& model = m_document->model();
    const std::string key = element.id.toStdString();
    switch (element.kind) {
    case ElementRef::Kind::Step: return model.step(key) != nullptr;
    case ElementRef::Kind::Transition: return model.transition(key) != nullptr;
    case ElementRef::Kind::GrafcetStep:
        return model.grafcet(key) && model.grafcet(key)->step(element.number) != nullptr;
    case ElementRef::Kind::GrafcetTransition:
        return model.grafcet(key) && model.grafcet(key)->transition(element.number) != nullptr;
    default: return false;
    }
}

void PropertyDock::onSelectionChanged(const ElementRef& element)
{
    const bool ofKind = element.kind == m_kind && !element.id.isEmpty();
    if (ofKind && element.id == m_elementId && element.number == m_number)
        return;
    const bool shown = ofKind && exists(element);
    m_elementId = shown ? element.id : QString();
    m_number = shown ? element.number : 0;
    refresh();
    if (!m_elementId.isEmpty())
        raiseOverPropertySibling(this);
}

void PropertyDock::onFocusFieldRequested(const ElementRef& element, const QString& field)
{
    if (element.kind != m_kind || element.id != m_elementId || element.number != m_number || m_elementId.isEmpty())
        return;
    revealDock(this);
    focusField(field);
}

} // namespace editor
