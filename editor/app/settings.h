#pragma once

#include "core/model/model.h"

#include <QByteArray>
#include <QSettings>
#include <QString>
#include <QStringList>

namespace editor {

// The user's preferences and the window's memory, typed. Every value has a
// default, and a stored value that makes no sense (an unknown dialect, a
// cycle time out of range) reads as the default, so a hand-edited or old
// settings file never breaks the editor.
class Settings {
public:
    static constexpr int kMinVerificationSeconds = 1;
    static constexpr int kMaxVerificationSeconds = 3600;
    static constexpr int kDefaultVerificationSeconds = 4;

    // Uses the application's QSettings (organisation and application names
    // set in main()).
    Settings() = default;

    // "" follows the system locale; otherwise a code of availableLanguages().
    QString language() const;
    void setLanguage(const QString& code);

    // What a new model starts with (the template has IEC and 20 ms).
    core::Dialect defaultDialect() const;
    // The template File > New offered last: "gemma", "packml-2015" or "packml-2022".
    QString newModelTemplate() const;
    void setNewModelTemplate(const QString& name);
    void setDefaultDialect(core::Dialect dialect);
    int defaultCycleTimeMs() const;
    void setDefaultCycleTimeMs(int milliseconds);

    // How long one verification may run before it stops, undecided where it
    // had to (GV100): 1 s to 1 h, 4 s by default as in ggstudio-cli verify.
    int verificationTimeLimitSeconds() const;
    void setVerificationTimeLimitSeconds(int seconds);

    bool showHidden() const;
    void setShowHidden(bool show);

    QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray& geometry);
    QByteArray windowState() const;
    void setWindowState(const QByteArray& state);
    // The docks (object names) the window state has tabbed behind another:
    // the next start's first frame leaves them out.
    QStringList tabbedBehindDocks() const;
    void setTabbedBehindDocks(const QStringList& names);
    // The property docks (object names) the user closed: the window state
    // alone cannot tell them from those the tab in front hid.
    QStringList closedDocks() const;
    void setClosedDocks(const QStringList& names);

    // Most recent first.
    QStringList recentFiles() const;
    void setRecentFiles(const QStringList& files);

    // The nested GRAFCET tabs a model file had open (GEMMA step ids, in tab
    // order) and the one in front ("" for the GEMMA chart), so that opening
    // the file again brings its tabs back. Kept for the recent files only.
    struct GrafcetTabs {
        QStringList steps;
        QString current;
    };
    GrafcetTabs grafcetTabs(const QString& filePath) const;
    void setGrafcetTabs(const QString& filePath, const GrafcetTabs& tabs);

    // The fallback (the model's own dialect) until the user has exported once.
    core::Dialect lastExportDialect(core::Dialect fallback) const;
    void setLastExportDialect(core::Dialect dialect);
    // The Structured Text export: one file per POU in a folder, or one file.
    bool lastStExportSingleFile() const;
    void setLastStExportSingleFile(bool singleFile);

    // Where the file dialogs start: models, and exported code or pictures.
    QString lastModelDirectory() const;
    void setLastModelDirectory(const QString& directory);
    QString lastExportDirectory() const;
    void setLastExportDirectory(const QString& directory);

    // Written to disk now (QSettings otherwise writes when idle or on exit).
    void sync();

private:
    core::Dialect dialectValue(const char* key, core::Dialect fallback) const;
    void setDialectValue(const char* key, core::Dialect dialect);

    mutable QSettings m_settings;
};

} // namespace editor
