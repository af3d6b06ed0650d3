#include "editor/app/recentfiles.h"

#include "editor/app/settings.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>

namespace editor {

namespace {

// One spelling per file, so the same model opened twice is listed once.
QString normalised(const QString& path)
{
    return QDir::cleanPath(QFileInfo(path).absoluteFilePath());
}

} // namespace

RecentFiles::RecentFiles(Settings& settings, QWidget* menuParent)
    : QObject(menuParent)
    , m_settings(settings)
    , m_menu(new QMenu(menuParent))
    , m_files(settings.recentFiles())
{
    m_menu->setObjectName("recentFilesMenu");
    retranslate();
}

void RecentFiles::add(const QString& path)
{
    const QString file = normalised(path);
    m_files.removeAll(file);
    m_files.prepend(file);
    store();
}

void RecentFiles::remove(const QString& path)
{
    m_files.removeAll(normalised(path));
    store();
}

void RecentFiles::clear()
{
    m_files.clear();
    store();
}

void RecentFiles::retranslate()
{
    m_menu->setTitle(tr("Open &Recent"));
    rebuildMenu();
}

void RecentFiles::store()
{
    m_settings.setRecentFiles(m_files);
    m_files = m_settings.recentFiles(); // the settings keep only so many
    rebuildMenu();
}

void RecentFiles::rebuildMenu()
{
    m_menu->clear();
    for (qsizetype i = 0; i < m_files.size(); ++i) {
        const QString& file = m_files[i];
        // Accelerators 1..9 for the first nine; '&' in names must not become one.
        QString name = QFileInfo(file).fileName().replace('&', "&&");
        const QString text = i < 9 ? QStringLiteral("&%1 %2").arg(i + 1).arg(name) : name;
        QAction* action = m_menu->addAction(text);
        action->setToolTip(QDir::toNativeSeparators(file));
        action->setStatusTip(QDir::toNativeSeparators(file));
        connect(action, &QAction::triggered, this, [this, file] { emit openRequested(file); });
    }
    m_menu->addSeparator();
    QAction* clearAction = m_menu->addAction(tr("&Clear Menu"));
    clearAction->setEnabled(!m_files.isEmpty());
    connect(clearAction, &QAction::triggered, this, &RecentFiles::clear);
    m_menu->setEnabled(!m_files.isEmpty());
}

} // namespace editor
