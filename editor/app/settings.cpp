#include "editor/app/settings.h"

#include <QDir>
#include <QFileInfo>
#include <QVariantMap>

#include <string>

namespace editor {

namespace {

constexpr int kMaxRecentFiles = 10;

} // namespace

QString Settings::language() const
{
    return m_settings.value("ui/language").toString();
}

void Settings::setLanguage(const QString& code)
{
    m_settings.setValue("ui/language", code);
}

core::Dialect Settings::defaultDialect() const
{
    return dialectValue("model/defaultDialect", core::Model().settings().dialect);
}

void Settings::setDefaultDialect(core::Dialect dialect)
{
    setDialectValue("model/defaultDialect", dialect);
}

QString Settings::newModelTemplate() const
{
    return m_settings.value("model/newModelTemplate", QStringLiteral("gemma")).toString();
}

void Settings::setNewModelTemplate(const QString& name)
{
    m_settings.setValue("model/newModelTemplate", name);
}

int Settings::defaultCycleTimeMs() const
{
    const int fallback = core::Model().settings().cycleTimeMs;
    bool ok = false;
    const int value = m_settings.value("model/defaultCycleTimeMs", fallback).toInt(&ok);
    return ok && value >= core::kMinCycleTimeMs && value <= core::kMaxCycleTimeMs ? value : fallback;
}

void Settings::setDefaultCycleTimeMs(int milliseconds)
{
    m_settings.setValue("model/defaultCycleTimeMs", milliseconds);
}

int Settings::verificationTimeLimitSeconds() const
{
    bool ok = false;
    const int value = m_settings.value("verification/timeLimitSeconds", kDefaultVerificationSeconds).toInt(&ok);
    return ok && value >= kMinVerificationSeconds && value <= kMaxVerificationSeconds ? value
                                                                                      : kDefaultVerificationSeconds;
}

void Settings::setVerificationTimeLimitSeconds(int seconds)
{
    m_settings.setValue("verification/timeLimitSeconds", seconds);
}

bool Settings::showHidden() const
{
    return m_settings.value("view/showHidden", false).toBool();
}

void Settings::setShowHidden(bool show)
{
    m_settings.setValue("view/showHidden", show);
}

QByteArray Settings::windowGeometry() const
{
    return m_settings.value("window/geometry").toByteArray();
}

void Settings::setWindowGeometry(const QByteArray& geometry)
{
    m_settings.setValue("window/geometry", geometry);
}

QByteArray Settings::windowState() const
{
    return m_settings.value("window/state").toByteArray();
}

void Settings::setWindowState(const QByteArray& state)
{
    m_settings.setValue("window/state", state);
}

QStringList Settings::tabbedBehindDocks() const
{
    return m_settings.value("window/tabbedBehind").toStringList();
}

void Settings::setTabbedBehindDocks(const QStringList& names)
{
    m_settings.setValue("window/tabbedBehind", names);
}

QStringList Settings::closedDocks() const
{
    return m_settings.value("window/closedDocks").toStringList();
}

void Settings::setClosedDocks(const QStringList& names)
{
    m_settings.setValue("window/closedDocks", names);
}

QStringList Settings::recentFiles() const
{
    QStringList files = m_settings.value("files/recent").toStringList();
    files.removeAll(QString());
    files.removeDuplicates();
    return files.mid(0, kMaxRecentFiles);
}

void Settings::setRecentFiles(const QStringList& files)
{
    m_settings.setValue("files/recent", files.mid(0, kMaxRecentFiles));
}

// One map from absolute file path to its tabs: QSettings keys cannot hold
// the slashes of a path.
Settings::GrafcetTabs Settings::grafcetTabs(const QString& filePath) const
{
    const QVariantMap files = m_settings.value("session/grafcetTabs").toMap();
    const QVariantMap entry = files.value(QDir::cleanPath(QFileInfo(filePath).absoluteFilePath())).toMap();
    GrafcetTabs tabs{entry.value("steps").toStringList(), entry.value("current").toString()};
    tabs.steps.removeAll(QString());
    tabs.steps.removeDuplicates();
    if (!tabs.steps.contains(tabs.current))
        tabs.current.clear();
    return tabs;
}

void Settings::setGrafcetTabs(const QString& filePath, const GrafcetTabs& tabs)
{
    QVariantMap files = m_settings.value("session/grafcetTabs").toMap();
    const QString key = QDir::cleanPath(QFileInfo(filePath).absoluteFilePath());
    if (tabs.steps.isEmpty())
        files.remove(key);
    else
        files.insert(key, QVariantMap{{"steps", tabs.steps}, {"current", tabs.current}});
    // Files no longer among the recent ones are forgotten, so the map stays small.
    const QStringList recent = recentFiles();
    for (auto it = files.begin(); it != files.end();) {
        if (it.key() != key && !recent.contains(it.key()))
            it = files.erase(it);
        else
            ++it;
    }
    m_settings.setValue("session/grafcetTabs", files);
}

core::Dialect Settings::lastExportDialect(core::Dialect fallback) const
{
    return dialectValue("export/dialect", fallback);
}

void Settings::setLastExportDialect(core::Dialect dialect)
{
    setDialectValue("export/dialect", dialect);
}

bool Settings::lastStExportSingleFile() const
{
    return m_settings.value("export/stSingleFile", false).toBool();
}

void Settings::setLastStExportSingleFile(bool singleFile)
{
    m_settings.setValue("export/stSingleFile", singleFile);
}

QString Settings::lastModelDirectory() const
{
    return m_settings.value("files/modelDirectory", QDir::homePath()).toString();
}

void Settings::setLastModelDirectory(const QString& directory)
{
    m_settings.setValue("files/modelDirectory", directory);
}

QString Settings::lastExportDirectory() const
{
    return m_settings.value("files/exportDirectory", lastModelDirectory()).toString();
}

void Settings::setLastExportDirectory(const QString& directory)
{
    m_settings.setValue("files/exportDirectory", directory);
}

void Settings::sync()
{
    m_settings.sync();
}

core::Dialect Settings::dialectValue(const char* key, core::Dialect fallback) const
{
    core::Dialect dialect = fallback;
    const std::string name = m_settings.value(key).toString().toStdString();
    if (name.empty() || !core::parseDialect(name, dialect))
        return fallback;
    return dialect;
}

void Settings::setDialectValue(const char* key, core::Dialect dialect)
{
    m_settings.setValue(key, QString::fromUtf8(core::dialectName(dialect).data(),
                                               static_cast<qsizetype>(core::dialectName(dialect).size())));
}

} // namespace editor
