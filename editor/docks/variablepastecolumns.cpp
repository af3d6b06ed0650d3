#include "editor/docks/variablepastecolumns.h"

#include "editor/app/languages.h"

#include <QTranslator>

#include <array>
#include <map>

namespace editor {

namespace {

enum class Field { Name, Type, Default, Comment, Kind };

struct FieldTitle {
    Field field;
    const char* english; // the table's header text, as in VariablesTableModel::headerData
};

constexpr std::array<FieldTitle, 5> kTitles{{
    {Field::Name, "Name"},
    {Field::Type, "Type"},
    {Field::Default, "Default"},
    {Field::Comment, "Comment"},
    {Field::Kind, "Kind"},
}};

// Every title, folded to lower case, in English and in each UI language:
// a table copied from a colleague's French editor pastes into an English one.
const std::map<QString, Field>& titles()
{
    static const std::map<QString, Field> all = [] {
        std::map<QString, Field> found;
        for (const FieldTitle& title : kTitles)
            found.emplace(QString::fromLatin1(title.english).toLower(), title.field);
        for (const UiLanguage& language : availableLanguages()) {
            QTranslator translator;
            if (!translator.load(QStringLiteral(":/i18n/ggstudio_") + language.code))
                continue;
            for (const FieldTitle& title : kTitles) {
                const QString translated = translator.translate("editor::VariablesTableModel", title.english);
                if (!translated.isEmpty())
                    found.emplace(translated.toLower(), title.field);
            }
        }
        return found;
    }();
    return all;
}

void place(VariablePasteColumns& columns, Field field, int cell)
{
    switch (field) {
    case Field::Name: columns.name = cell; break;
    case Field::Type: columns.type = cell; break;
    case Field::Default: columns.defaultValue = cell; break;
    case Field::Comment: columns.comment = cell; break;
    case Field::Kind:
        columns.kind = cell;
        columns.kindDeclared = true;
        break;
    }
}

} // namespace

std::optional<VariablePasteColumns> headerColumns(const QStringList& cells)
{
    // A header names its columns; the fields it leaves out are not pasted.
    VariablePasteColumns columns{-1, -1, -1, -1, -1, false};
    for (int cell = 0; cell < cells.size(); ++cell) {
        const QString text = cells[cell].trimmed().toLower();
        if (text.isEmpty())
            continue;
        const auto title = titles().find(text);
        if (title == titles().end())
            return std::nullopt;
        place(columns, title->second, cell);
    }
    if (columns.name < 0)
        return std::nullopt;
    return columns;
}

} // namespace editor
