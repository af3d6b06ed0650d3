#include "editor/window/grafcettabs.h"

#include "editor/app/settings.h"
#include "editor/document.h"
#include "editor/grafcet/grafcetactions.h"
#include "editor/grafcet/grafcetkeyboard.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/grafcet/grafcetselectionsync.h"
#include "editor/grafcet/grafcetview.h"
#include "editor/grafcet/nestedgrafcetavailable.h"
#include "editor/text/gemmastatenames.h"
#include "editor/text/packmltexts.h"

#include "core/templates/packml/packmlconfiguration.h"

#include <QTabWidget>

namespace editor {

namespace {

// The PackML (mode, state) of a tab's key, when the model is PackML and the key one of its.
std::optional<std::pair<const core::packml::Mode*, core::packml::State>> packmlPlace(const core::Model& model,
                                                                                    const QString& key)
{
    const core::packml::Configuration* configuration = model.packml();
    if (!configuration)
        return std::nullopt;
    const auto parsed = core::packml::parseGrafcetKey(key.toStdString());
    if (!parsed)
        return std::nullopt;
    const core::packml::Mode* mode = configuration->mode(parsed->first);
    if (!mode)
        return std::nullopt;
    return std::make_pair(mode, parsed->second);
}

QString modeName(const core::packml::Mode& mode)
{
    const std::string_view name = mode.displayName();
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

} // namespace

GrafcetTabs::GrafcetTabs(QTabWidget* tabs, Document* document, Selection* selection, Settings* settings,
                         QObject* parent)
    : QObject(parent)
    , m_tabs(tabs)
    , m_document(document)
    , m_selection(selection)
    , m_settings(settings)
{
}

GrafcetView* GrafcetTabs::view(const QString& key) const
{
    for (int i = 1; i < m_tabs->count(); ++i) {
        auto* view = qobject_cast<GrafcetView*>(m_tabs->widget(i));
        if (view && view->grafcetScene()->stepId() == key)
            return view;
    }
    return nullptr;
}

GrafcetView* GrafcetTabs::viewInFront() const
{
    return qobject_cast<GrafcetView*>(m_tabs->currentWidget());
}

// A PackML GRAFCET opens where the model has it (the state's choice is
// Own); a GEMMA macro-step or enclosing step opens without one, on a
// drawing that offers to create it.
bool GrafcetTabs::canOpen(const QString& key) const
{
    const core::Model& model = m_document->model();
    if (model.templateKind() == core::TemplateKind::PackML)
        return packmlPlace(model, key) && model.grafcet(key.toStdString());
    return canOpenNestedGrafcet(model, key);
}

bool GrafcetTabs::open(const QString& key)
{
    if (!canOpen(key))
        return false;
    GrafcetView* grafcetView = view(key);
    if (!grafcetView) {
        auto* scene = new GrafcetScene(m_document, key);
        grafcetView = new GrafcetView(scene);
        scene->setParent(grafcetView);
        emit viewOpened(grafcetView); // marked at once when opened during a simulation
        auto* actions = new GrafcetActions(*m_document, *grafcetView);
        connect(actions, &GrafcetActions::statusMessage, this, &GrafcetTabs::statusMessage);
        grafcetView->setObjectName(QStringLiteral("grafcetView_") + key);
        m_tabs->addTab(grafcetView, QString());
        retitle();
        m_tabs->setCurrentWidget(grafcetView);
        // Once shown, so that the view scrolls to a selected element after its first placing.
        new GrafcetSelectionSync(grafcetView, m_selection);
        new GrafcetKeyboard(grafcetView, m_selection);
    }
    m_tabs->setCurrentWidget(grafcetView); // remembered through currentChanged when it changes
    return true;
}

void GrafcetTabs::close(int index)
{
    if (index <= 0) // the chart
        return;
    QWidget* closing = m_tabs->widget(index);
    if (!qobject_cast<GrafcetView*>(closing)) // the Machine tab comes and goes with the machine
        return;
    m_tabs->removeTab(index);
    delete closing;
    remember();
}

void GrafcetTabs::closeAll()
{
    for (int i = m_tabs->count() - 1; i > 0; --i) {
        QWidget* closing = m_tabs->widget(i);
        if (!qobject_cast<GrafcetView*>(closing))
            continue;
        m_tabs->removeTab(i);
        delete closing;
    }
}

// A macro-step's tab stays while its GRAFCET does, as a PackML state's.
void GrafcetTabs::closeStale()
{
    const core::Model& model = m_document->model();
    for (int i = m_tabs->count() - 1; i > 0; --i) {
        auto* grafcetView = qobject_cast<GrafcetView*>(m_tabs->widget(i));
        if (grafcetView && !model.grafcet(grafcetView->grafcetScene()->stepId().toStdString()))
            close(i);
    }
    retitle();
}

QString GrafcetTabs::title(const QString& key) const
{
    if (const auto place = packmlPlace(m_document->model(), key))
        return tr("%1 · %2").arg(modeName(*place->first), packmltext::stateName(place->second));
    return QStringLiteral("%1 %2").arg(key, officialStateName(key));
}

QString GrafcetTabs::toolTip(const QString& key) const
{
    if (const auto place = packmlPlace(m_document->model(), key))
        return tr("The GRAFCET of %1 in the mode %2")
            .arg(packmltext::stateName(place->second), modeName(*place->first));
    return tr("The nested GRAFCET of %1").arg(key);
}

void GrafcetTabs::retitle()
{
    const bool packml = m_document->model().templateKind() == core::TemplateKind::PackML;
    m_tabs->setTabText(0, packml ? tr("PackML Chart") : tr("GEMMA Chart"));
    for (int i = 1; i < m_tabs->count(); ++i) {
        auto* grafcetView = qobject_cast<GrafcetView*>(m_tabs->widget(i));
        if (!grafcetView)
            continue;
        const QString key = grafcetView->grafcetScene()->stepId();
        m_tabs->setTabText(i, title(key));
        m_tabs->setTabToolTip(i, toolTip(key));
    }
}

void GrafcetTabs::remember()
{
    if (m_switchingFile || m_document->filePath().isEmpty())
        return;
    Settings::GrafcetTabs tabs;
    for (int i = 1; i < m_tabs->count(); ++i) {
        if (auto* grafcetView = qobject_cast<GrafcetView*>(m_tabs->widget(i)))
            tabs.steps << grafcetView->grafcetScene()->stepId();
    }
    if (GrafcetView* front = viewInFront())
        tabs.current = front->grafcetScene()->stepId();
    m_settings->setGrafcetTabs(m_document->filePath(), tabs);
}

// The tabs of GRAFCETs the file no longer has (edited elsewhere) stay closed.
void GrafcetTabs::restore()
{
    const Settings::GrafcetTabs tabs = m_settings->grafcetTabs(m_document->filePath());
    m_switchingFile = true;
    for (const QString& key : tabs.steps)
        open(key);
    if (GrafcetView* front = view(tabs.current))
        m_tabs->setCurrentWidget(front);
    else
        m_tabs->setCurrentIndex(0);
    m_switchingFile = false;
    remember();
}

} // namespace editor
