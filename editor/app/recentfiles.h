#pragma once

#include <QObject>
#include <QStringList>

class QMenu;
class QWidget;

namespace editor {

class Settings;

// The File > Open Recent menu: the last opened or saved models, most recent
// first, kept in the settings. Files that no longer exist stay listed (a
// network drive may be away) until opening them fails.
class RecentFiles : public QObject {
    Q_OBJECT

public:
    RecentFiles(Settings& settings, QWidget* menuParent);

    QMenu* menu() const { return m_menu; }
    QStringList files() const { return m_files; }

    void add(const QString& path);
    void remove(const QString& path);
    void clear();

    void retranslate();

signals:
    void openRequested(const QString& path);

private:
    void store();
    void rebuildMenu();

    Settings& m_settings;
    QMenu* m_menu;
    QStringList m_files;
};

} // namespace editor
