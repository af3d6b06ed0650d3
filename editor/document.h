#pragma once

#include "editor/elementref.h"

#include "core/checks/diagnostic.h"
#include "core/checks/incrementalcheck.h"
#include "core/model/model.h"
#include "core/formats/modelfiles.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

class QUndoStack;
class QUndoCommand;

namespace editor {

class ModelCommand;

// The open model: owns the core::Model and its QUndoStack, and is the only
// way to change them. Every edit is a QUndoCommand pushed with push(); the
// commands (editor/commands/) call the model's operations through model().
// The core model's change events come out as typed Qt signals, which the
// chart, the docks and the window observe.
class Document : public QObject {
    Q_OBJECT

public:
    // The template with the default settings.
    explicit Document(QObject* parent = nullptr);
    // Starts on `model` (untitled, native format), as replaceModel would.
    explicit Document(const core::Model& model, QObject* parent = nullptr);
    ~Document() override;

    const core::Model& model() const { return *m_model; }
    // For undo commands only: everything else edits by pushing commands.
    core::Model& modelForCommands() { return *m_model; }

    QUndoStack* undoStack() const { return m_undoStack; }
    // Takes ownership and runs redo(). For a ModelCommand (editor/commands/)
    // whose model operation fails, returns false and emits editFailed(): the
    // command never enters the undo stack and the redo history stays. A
    // ModelCommand that changes nothing is dropped as well (returns true).
    bool push(QUndoCommand* command);

    // While read-only (simulation mode) push() refuses every command: it
    // emits editFailed() and returns false. Loading or replacing the model
    // is still allowed: the simulation ends when the model it runs goes.
    bool isReadOnly() const { return m_readOnly; }
    void setReadOnly(bool readOnly);

    // Checks of the current model, recomputed after every edit (a command's
    // redo or undo, a load); diagnosticsChanged() is emitted when they differ.
    // The typed signals of an edit come when it is complete, after the checks,
    // so a slot always sees a whole model and its current diagnostics.
    const std::vector<core::Diagnostic>& diagnostics() const { return m_diagnostics; }
    std::vector<core::Diagnostic> diagnosticsFor(const ElementRef& element) const;
    bool hasProblems(const ElementRef& element) const; // any error or warning
    // The errors and warnings of the steps and transitions of the nested
    // GRAFCET of GEMMA step `stepId` (not those of the GRAFCET as a whole,
    // which are the step's own).
    int nestedProblemCount(const QString& stepId) const;

    // Files. A failed load leaves the open model untouched and returns false
    // with the reason in errorMessage ("FILE: LOCATION: MESSAGE"). A load that
    // did not take over everything in the file (a PLCopen file whose code was
    // edited, GG Studio keys in a GG-Generator file) says what in warnings
    // ("FILE: LOCATION: warning: MESSAGE", one per entry).
    bool load(const QString& path, QString* errorMessage, QStringList* warnings = nullptr);
    bool save(const QString& path, QString* errorMessage); // native JSON, atomic
    void newFromTemplate();
    // Replaces the whole model (for recovery and import); clears undo history.
    // Emits modelReset(), then modelReplaced().
    void replaceModel(const core::Model& model, const QString& path, core::ModelFormat format);

    QString filePath() const { return m_filePath; }
    core::ModelFormat fileFormat() const { return m_fileFormat; }
    // "Untitled" or the file's base name.
    QString displayName() const;
    bool isModified() const;

signals:
    void stepChanged(const QString& id);
    void transitionChanged(const QString& id);
    void variableChanged(const QString& name);
    void variablesChanged(); // added, removed, renamed or moved
    void settingsChanged();
    void propertiesChanged(); // the verification properties: added, removed, edited or moved
    void grafcetChanged(const QString& stepId); // something in the nested GRAFCET of a GEMMA step (or packml::grafcetKey)
    // PackML models only (spec packml.md §3, §5.1).
    void packmlSettingsChanged(); // edition, options, initial state or initial mode
    void commandChanged(const QString& command); // its condition or comment ("Reset")
    void modesChanged(); // a unit mode added or removed
    void modeChanged(int mode); // its name, comment, request, listings or GRAFCET choices
    void machineChanged(); // the virtual machine's description (core/machine/machine.h)
    void modelReset();        // everything may have changed
    // After modelReset: a new model (New, Open, an example, a recovery), not an edit of this one.
    void modelReplaced();
    void diagnosticsChanged();
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);
    void readOnlyChanged(bool readOnly);
    // An edit was refused (its model operation failed); the message is for the user.
    void editFailed(const QString& message);

private:
    friend class ModelCommand; // brackets its model operations, reports failures

    void beginEdit();
    void endEdit();
    void reportEditFailure(const QString& message);
    void onModelChanged(const core::ModelChange& change);
    void emitChange(const core::ModelChange& change);
    bool recheck(); // true when the diagnostics changed

    std::unique_ptr<core::Model> m_model;
    QUndoStack* m_undoStack;
    std::vector<core::Diagnostic> m_diagnostics;
    core::IncrementalCheck m_checks; // what m_diagnostics came from
    std::vector<core::ModelChange> m_uncheckedChanges; // since the last check, in order
    QString m_filePath;
    core::ModelFormat m_fileFormat = core::ModelFormat::Native;
    int m_observer = 0;
    int m_editDepth = 0;
    bool m_recheckQueued = false;
    bool m_readOnly = false;
    std::vector<core::ModelChange> m_pendingChanges; // of the edit under way
};

} // namespace editor
