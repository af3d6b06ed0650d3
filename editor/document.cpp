#include "editor/document.h"

#include "editor/commands/modelcommand.h"

#include "core/model/iectypes.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoCommand>
#include <QUndoStack>

#include <algorithm>

namespace editor {

namespace {

core::Diagnostic::Target diagnosticTarget(ElementRef::Kind kind)
{
    switch (kind) {
    case ElementRef::Kind::Step:
        return core::Diagnostic::Target::Step;
    case ElementRef::Kind::Transition:
        return core::Diagnostic::Target::Transition;
    case ElementRef::Kind::Variable:
        return core::Diagnostic::Target::Variable;
    case ElementRef::Kind::GrafcetStep:
        return core::Diagnostic::Target::GrafcetStep;
    case ElementRef::Kind::GrafcetTransition:
        return core::Diagnostic::Target::GrafcetTransition;
    case ElementRef::Kind::PackmlState:
        return core::Diagnostic::Target::ModeState;
    case ElementRef::Kind::PackmlCommand:
        return core::Diagnostic::Target::Command;
    case ElementRef::Kind::PackmlMode:
        return core::Diagnostic::Target::Mode;
    case ElementRef::Kind::Model:
    case ElementRef::Kind::None:
    case ElementRef::Kind::PackmlTransition: // the checks report a transition's problem on its command
        break;
    }
    return core::Diagnostic::Target::Model;
}

// A PackML mode owns its request's diagnostics too; a state shown in no
// particular mode (number 0) owns those of every mode.
bool concernsPackml(const core::Diagnostic& diagnostic, const ElementRef& element)
{
    using Target = core::Diagnostic::Target;
    switch (element.kind) {
    case ElementRef::Kind::PackmlMode:
        return (diagnostic.target == Target::Mode || diagnostic.target == Target::Request)
            && diagnostic.mode == element.number;
    case ElementRef::Kind::PackmlState:
        return diagnostic.target == Target::ModeState && diagnostic.state == element.id.toStdString()
            && (element.number == 0 || diagnostic.mode == element.number);
    case ElementRef::Kind::PackmlCommand:
        return diagnostic.target == Target::Command && diagnostic.element == element.id.toStdString();
    default: return false;
    }
}

bool concerns(const core::Diagnostic& diagnostic, const ElementRef& element)
{
    switch (element.kind) {
    case ElementRef::Kind::PackmlMode:
    case ElementRef::Kind::PackmlState:
    case ElementRef::Kind::PackmlCommand:
    case ElementRef::Kind::PackmlTransition: return concernsPackml(diagnostic, element);
    default: break;
    }
    if (element.isNull() || diagnostic.target != diagnosticTarget(element.kind))
        return false;
    if (element.kind == ElementRef::Kind::Model)
        return true;
    const std::string id = element.id.toStdString();
    if (element.isNested())
        return diagnostic.element == id && diagnostic.nestedNumber == element.number;
    // IEC names ignore case, so "start" and "Start" are the same variable.
    return element.kind == ElementRef::Kind::Variable ? core::equalsIgnoreCase(diagnostic.element, id)
                                                      : diagnostic.element == id;
}

std::string localPath(const QString& path)
{
    return QFile::encodeName(path).toStdString();
}

} // namespace

Document::Document(QObject* parent)
    : Document(core::Model(), parent)
{
}

Document::Document(const core::Model& model, QObject* parent)
    : QObject(parent)
    , m_model(std::make_unique<core::Model>(model))
    , m_undoStack(new QUndoStack(this))
{
    m_observer = m_model->addObserver([this](const core::ModelChange& change) { onModelChanged(change); });
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
    m_diagnostics = m_checks.checkAll(*m_model);
}

Document::~Document()
{
    // No signals about a model that is going away.
    m_model->removeObserver(m_observer);
}

bool Document::push(QUndoCommand* command)
{
    if (m_readOnly) {
        delete command;
        emit editFailed(tr("Stop the simulation to edit the model"));
        return false;
    }
    // Apply before QUndoStack::push: the stack drops its redo history on
    // every push, even of a command it then discards as obsolete.
    auto* modelCommand = dynamic_cast<ModelCommand*>(command);
    if (modelCommand && !modelCommand->applyBeforePush()) {
        const bool failed = modelCommand->hasFailed();
        delete command;
        return !failed;
    }
    m_undoStack->push(command);
    return true;
}

void Document::setReadOnly(bool readOnly)
{
    if (m_readOnly == readOnly)
        return;
    m_readOnly = readOnly;
    emit readOnlyChanged(m_readOnly);
}

void Document::reportEditFailure(const QString& message)
{
    emit editFailed(message);
}

std::vector<core::Diagnostic> Document::diagnosticsFor(const ElementRef& element) const
{
    std::vector<core::Diagnostic> result;
    std::copy_if(m_diagnostics.begin(), m_diagnostics.end(), std::back_inserter(result),
                 [&](const core::Diagnostic& d) { return concerns(d, element); });
    return result;
}

bool Document::hasProblems(const ElementRef& element) const
{
    return std::any_of(m_diagnostics.begin(), m_diagnostics.end(), [&](const core::Diagnostic& d) {
        return d.severity != core::Severity::Info && concerns(d, element);
    });
}

int Document::nestedProblemCount(const QString& stepId) const
{
    const std::string id = stepId.toStdString();
    return static_cast<int>(std::count_if(m_diagnostics.begin(), m_diagnostics.end(), [&](const core::Diagnostic& d) {
        const bool nested = d.target == core::Diagnostic::Target::GrafcetStep
                         || d.target == core::Diagnostic::Target::GrafcetTransition;
        return nested && d.severity != core::Severity::Info && d.element == id;
    }));
}

bool Document::load(const QString& path, QString* errorMessage, QStringList* warnings)
{
    core::LoadedModel loaded = core::loadSupportedModelFile(localPath(path), core::TemplateSupport::GemmaAndPackML);
    if (!loaded.ok()) {
        if (loaded.error.file.empty() || loaded.error.file == localPath(path))
            loaded.error.file = path.toStdString(); // show the path as the user gave it
        if (errorMessage)
            *errorMessage = QString::fromStdString(loaded.error.toString());
        return false;
    }
    if (warnings) {
        warnings->clear();
        for (core::LoadWarning& warning : loaded.warnings) {
            if (warning.file.empty() || warning.file == localPath(path))
                warning.file = path.toStdString();
            warnings->append(QString::fromStdString(warning.toString()));
        }
    }
    replaceModel(*loaded.model, path, loaded.format);
    return true;
}

bool Document::save(const QString& path, QString* errorMessage)
{
    const core::Status status = core::saveModelFile(*m_model, localPath(path), core::ModelFormat::Native);
    if (!status) {
        if (errorMessage)
            *errorMessage = tr("%1: %2").arg(path, QString::fromStdString(status.message));
        return false;
    }
    m_fileFormat = core::ModelFormat::Native;
    if (m_filePath != path) {
        m_filePath = path;
        emit filePathChanged(m_filePath);
    }
    m_undoStack->setClean();
    return true;
}

void Document::newFromTemplate()
{
    replaceModel(core::Model(), QString(), core::ModelFormat::Native);
}

void Document::replaceModel(const core::Model& model, const QString& path, core::ModelFormat format)
{
    // History first: its commands describe the old model.
    m_undoStack->clear();
    m_model->assign(model);
    m_fileFormat = format;
    if (m_filePath != path) {
        m_filePath = path;
        emit filePathChanged(m_filePath);
    }
    emit modelReplaced();
}

QString Document::displayName() const
{
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

bool Document::isModified() const
{
    return !m_undoStack->isClean();
}

void Document::beginEdit()
{
    ++m_editDepth;
}

void Document::endEdit()
{
    if (--m_editDepth > 0)
        return;
    std::vector<core::ModelChange> changes;
    changes.swap(m_pendingChanges);
    if (changes.empty())
        return;
    const bool diagnosticsDiffer = recheck();
    // One signal per element, in the order of their first change.
    std::vector<core::ModelChange> emitted;
    for (const core::ModelChange& change : changes) {
        const bool seen = std::any_of(emitted.begin(), emitted.end(), [&](const core::ModelChange& other) {
            return other.kind == change.kind && other.id == change.id;
        });
        if (!seen) {
            emitted.push_back(change);
            emitChange(change);
        }
    }
    if (diagnosticsDiffer)
        emit diagnosticsChanged();
}

void Document::onModelChanged(const core::ModelChange& change)
{
    // The model notifies in the middle of an operation, when its invariants
    // may not hold yet (no initial step for a moment): a command's changes
    // wait for the end of the command.
    m_uncheckedChanges.push_back(change);
    if (m_editDepth > 0) {
        m_pendingChanges.push_back(change);
        return;
    }
    if (change.kind == core::ModelChange::Kind::Reset) {
        // A whole model assigned (load, replace): complete, so check it first.
        const bool diagnosticsDiffer = recheck();
        emitChange(change);
        if (diagnosticsDiffer)
            emit diagnosticsChanged();
        return;
    }
    // Edited around the commands: the model may be mid-operation, so check
    // once control is back in the event loop.
    emitChange(change);
    if (!m_recheckQueued) {
        m_recheckQueued = true;
        QMetaObject::invokeMethod(
            this,
            [this] {
                m_recheckQueued = false;
                if (recheck())
                    emit diagnosticsChanged();
            },
            Qt::QueuedConnection);
    }
}

void Document::emitChange(const core::ModelChange& change)
{
    const QString id = QString::fromStdString(change.id);
    switch (change.kind) {
    case core::ModelChange::Kind::Step:
        emit stepChanged(id);
        break;
    case core::ModelChange::Kind::Transition:
        emit transitionChanged(id);
        break;
    case core::ModelChange::Kind::Variable:
        emit variableChanged(id);
        break;
    case core::ModelChange::Kind::VariableList:
        emit variablesChanged();
        break;
    case core::ModelChange::Kind::Settings:
        emit settingsChanged();
        break;
    case core::ModelChange::Kind::Grafcet:
        emit grafcetChanged(id);
        break;
    case core::ModelChange::Kind::Properties:
        emit propertiesChanged();
        break;
    case core::ModelChange::Kind::Reset:
        emit modelReset();
        break;
    case core::ModelChange::Kind::PackMLSettings:
        emit packmlSettingsChanged();
        break;
    case core::ModelChange::Kind::PackMLCommand:
        emit commandChanged(id);
        break;
    case core::ModelChange::Kind::PackMLModes:
        emit modesChanged();
        break;
    case core::ModelChange::Kind::PackMLMode:
        emit modeChanged(id.toInt());
        break;
    case core::ModelChange::Kind::Machine:
        emit machineChanged();
        break;
    }
}

bool Document::recheck()
{
    // A receptivity edit recomputes what it can affect; anything else
    // checks the whole model (core/checks/incrementalcheck.h).
    std::vector<core::Diagnostic> diagnostics = m_checks.update(*m_model, m_uncheckedChanges);
    m_uncheckedChanges.clear();
    if (diagnostics == m_diagnostics)
        return false;
    m_diagnostics = std::move(diagnostics);
    return true;
}

} // namespace editor
