#pragma once

#include <QList>
#include <QObject>
#include <QString>

class QTranslator;

namespace editor {

// A language the user interface is offered in. English is the source
// language of every tr() text; the others come from translations/*.ts,
// compiled into the editor library under :/i18n.
struct UiLanguage {
    QString code;       // "en", "fr", ...
    QString nativeName; // "English", "Français": never translated, so anyone finds their own
};

// In menu order, English first.
QList<UiLanguage> availableLanguages();

// The available language the system locale asks for, or "en".
QString systemLanguage();

// The translators of the running application: GG Studio's own texts and Qt's
// (standard dialog buttons, context menus). Switching installs the new ones
// and removes the old; QCoreApplication then sends QEvent::LanguageChange to
// every widget, whose changeEvent() retranslates it.
class Translators : public QObject {
    Q_OBJECT

public:
    explicit Translators(QObject* parent = nullptr);
    ~Translators() override;

    // "" means systemLanguage(). An unknown code falls back to English and
    // returns false.
    bool setLanguage(const QString& code);
    QString language() const { return m_language; } // the code in effect

private:
    void removeInstalled();

    QString m_language = QStringLiteral("en");
    QTranslator* m_appTranslator = nullptr;
    QTranslator* m_qtTranslator = nullptr;
};

} // namespace editor
