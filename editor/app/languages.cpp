#include "editor/app/languages.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

#include <algorithm>

namespace editor {

namespace {

bool isAvailable(const QString& code)
{
    const QList<UiLanguage> languages = availableLanguages();
    return std::any_of(languages.begin(), languages.end(),
                       [&](const UiLanguage& language) { return language.code == code; });
}

} // namespace

QList<UiLanguage> availableLanguages()
{
    return {
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("fr"), QStringLiteral("Français")},
        {QStringLiteral("es"), QStringLiteral("Español")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("it"), QStringLiteral("Italiano")},
    };
}

QString systemLanguage()
{
    // uiLanguages() lists the user's preferences in order ("fr-CA", "fr", "en-US").
    for (const QString& name : QLocale::system().uiLanguages()) {
        const QString code = QLocale(name).name().section('_', 0, 0);
        if (isAvailable(code))
            return code;
    }
    return QStringLiteral("en");
}

Translators::Translators(QObject* parent)
    : QObject(parent)
{
}

Translators::~Translators()
{
    removeInstalled();
}

bool Translators::setLanguage(const QString& code)
{
    const QString wanted = code.isEmpty() ? systemLanguage() : code;
    const bool known = isAvailable(wanted);
    const QString language = known ? wanted : QStringLiteral("en");

    removeInstalled();
    m_language = language;
    const QLocale locale(language);

    // English needs its translator too: it carries the plural forms ("%n error(s)").
    m_appTranslator = new QTranslator(this);
    if (m_appTranslator->load(locale, QStringLiteral("ggstudio"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(m_appTranslator);

    m_qtTranslator = new QTranslator(this);
    if (language != QLatin1String("en")
        && m_qtTranslator->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                                QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(m_qtTranslator);
    return known;
}

void Translators::removeInstalled()
{
    for (QTranslator** translator : {&m_appTranslator, &m_qtTranslator}) {
        if (*translator) {
            QCoreApplication::removeTranslator(*translator);
            delete *translator;
            *translator = nullptr;
        }
    }
}

} // namespace editor
