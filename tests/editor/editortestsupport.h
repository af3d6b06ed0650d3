#pragma once

// What the editor's window tests share: settings kept away from the user's,
// a shown main window, counting chart items.

#include "editor/app/languages.h"
#include "editor/mainwindow.h"
#include "editor/window/newmodeldialog.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QTimer>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QLatin1String>
#include <QMenu>
#include <QSettings>
#include <QStandardPaths>
#include <QString>

#include <memory>

namespace editortest {

// QSettings in INI files under `folder`, and the autosave folder in
// QStandardPaths' test location, so that no test reads or writes the user's.
inline void useTestSettings(const QString& folder, const QString& testName)
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder);
    QCoreApplication::setOrganizationName(QStringLiteral("GG Studio Tests"));
    QCoreApplication::setApplicationName(testName);
}

// The main window at the size of the smallest screen GG Studio is laid out
// for, shown; the caller waits for it to be exposed (QTest::qWaitForWindowExposed).
inline std::unique_ptr<editor::MainWindow> showMainWindow(editor::Translators& translators)
{
    auto window = std::make_unique<editor::MainWindow>(translators);
    window->resize(1366, 768);
    window->show();
    return window;
}

// showMainWindow() with fresh translators set to English, kept in `translators`.
inline std::unique_ptr<editor::MainWindow> showEnglishMainWindow(std::unique_ptr<editor::Translators>& translators)
{
    translators = std::make_unique<editor::Translators>();
    translators->setLanguage(QStringLiteral("en"));
    return showMainWindow(*translators);
}

// The child of `parent` with that object name; warns when there is none,
// so that a failing test says which it looked for.
template <typename T>
T* namedChild(const QObject& parent, const char* name)
{
    T* found = parent.findChild<T*>(QLatin1String(name));
    if (!found)
        qWarning("no child %s", name);
    return found;
}

template <typename Item>
int countItems(const QGraphicsScene& scene)
{
    int count = 0;
    for (QGraphicsItem* item : scene.items()) {
        if (item->type() == Item::Type)
            ++count;
    }
    return count;
}

// Answers the next File > New dialog once it shows: picks `choice` (the
// object name of its radio button, "templateGemma"...) and accepts, or
// rejects when `choice` is empty.
inline void answerNewModel(const char* choice)
{
    struct Poll {
        const char* choice;
        void operator()() const
        {
            auto* dialog = qobject_cast<editor::NewModelDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                QTimer::singleShot(10, *this);
                return;
            }
            if (!choice || !*choice) {
                dialog->reject();
                return;
            }
            if (auto* button = dialog->findChild<QAbstractButton*>(QLatin1String(choice)))
                button->click();
            dialog->accept();
        }
    };
    QTimer::singleShot(0, Poll{choice});
}

// Triggers, in the next popup menu to open, the enabled action whose text
// without its mnemonic is `text` and that follows the section titled
// `section` (any section when empty), then closes the menu; `found` says
// whether it was there. Call it just before what opens the menu.
inline void triggerInNextMenu(const QString& section, const QString& text, bool* found)
{
    *found = false;
    QTimer::singleShot(0, [section, text, found] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (!menu)
            return;
        bool inSection = section.isEmpty();
        for (QAction* action : menu->actions()) {
            if (action->isSeparator() && !action->text().isEmpty())
                inSection = section.isEmpty() || action->text() == section;
            else if (inSection && !*found && action->isEnabled() && action->text().remove(QLatin1Char('&')) == text) {
                *found = true;
                action->trigger();
            }
        }
        menu->close();
    });
}

} // namespace editortest
