#include "editor/docks/variablestablemodel.h"

#include "editor/commands/renamevariablecommand.h"
#include "editor/commands/setvariablecommentcommand.h"
#include "editor/commands/setvariabledefaultcommand.h"
#include "editor/commands/setvariablekindcommand.h"
#include "editor/commands/setvariabletypecommand.h"
#include "editor/docks/variablepastecolumns.h"
#include "editor/document.h"
#include "editor/stdstring.h"
#include "editor/text/diagnostictext.h"

#include "editor/style/secondarytext.h"

#include "core/model/iectypes.h"

#include <QColor>
#include <QFont>
#include <QPalette>

#include <optional>
#include <utility>

namespace editor {

namespace {

QString fieldOfColumn(int column)
{
    switch (column) {
    case VariablesTableModel::NameColumn:
        return QStringLiteral("name");
    case VariablesTableModel::TypeColumn:
        return QStringLiteral("type");
    case VariablesTableModel::KindColumn:
        return QStringLiteral("kind");
    case VariablesTableModel::DefaultColumn:
        return QStringLiteral("default");
    case VariablesTableModel::CommentColumn:
        return QStringLiteral("comment");
    default:
        return {};
    }
}

QString supportedTypes()
{
    QStringList names;
    for (core::IecType type : core::allIecTypes())
        names << fromStd(std::string(core::iecTypeName(type)));
    return names.join(QLatin1String(", "));
}

// A cell of the clipboard format holds no tab or line break.
QString cellText(const std::string& text)
{
    QString cell = fromStd(text);
    for (QChar& c : cell) {
        if (c == u'\t' || c == u'\n' || c == u'\r')
            c = u' ';
    }
    return cell;
}

constexpr core::VariableKind kKinds[]
    = { core::VariableKind::Input, core::VariableKind::Output, core::VariableKind::Internal };

QString kindFileName(core::VariableKind kind)
{
    return fromStd(std::string(core::variableKindName(kind)));
}

} // namespace

VariablesTableModel::VariablesTableModel(Document* document, QObject* parent)
    : QAbstractTableModel(parent)
    , m_document(document)
    , m_rowCount(static_cast<int>(document->model().variables().size()))
{
    connect(m_document, &Document::variablesChanged, this, &VariablesTableModel::onVariablesChanged);
    connect(m_document, &Document::modelReset, this, &VariablesTableModel::onVariablesChanged);
    connect(m_document, &Document::variableChanged, this, &VariablesTableModel::onVariableChanged);
    connect(m_document, &Document::diagnosticsChanged, this, &VariablesTableModel::onDiagnosticsChanged);
}

int VariablesTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_rowCount;
}

int VariablesTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

const core::Variable* VariablesTableModel::variableAt(int row) const
{
    const std::vector<core::Variable>& variables = m_document->model().variables();
    if (row < 0 || row >= m_rowCount || static_cast<std::size_t>(row) >= variables.size())
        return nullptr;
    return &variables[static_cast<std::size_t>(row)];
}

QString VariablesTableModel::variableName(int row) const
{
    const core::Variable* variable = variableAt(row);
    return variable ? fromStd(variable->name) : QString();
}

int VariablesTableModel::rowOf(const QString& name) const
{
    const int index = m_document->model().variableIndex(name.toStdString());
    return index < m_rowCount ? index : -1;
}

QString VariablesTableModel::kindText(core::VariableKind kind)
{
    switch (kind) {
    case core::VariableKind::Output:
        return tr("Output");
    case core::VariableKind::Internal:
        return tr("Internal");
    case core::VariableKind::Input:
        break;
    }
    return tr("Input");
}

std::optional<core::VariableKind> VariablesTableModel::parseKind(const QString& text)
{
    const QString trimmed = text.trimmed();
    for (core::VariableKind kind : kKinds) {
        if (trimmed.compare(kindFileName(kind), Qt::CaseInsensitive) == 0
            || trimmed.compare(kindText(kind), Qt::CaseInsensitive) == 0)
            return kind;
    }
    return std::nullopt;
}

int VariablesTableModel::columnOfField(const QString& field)
{
    for (int column = 0; column < ColumnCount; ++column) {
        if (fieldOfColumn(column) == field)
            return column;
    }
    return -1;
}

std::vector<core::Diagnostic> VariablesTableModel::diagnostics(const core::Variable& variable, int column) const
{
    const std::string field = fieldOfColumn(column).toStdString();
    std::vector<core::Diagnostic> result;
    for (core::Diagnostic& diagnostic : m_document->diagnosticsFor(ElementRef::variable(fromStd(variable.name)))) {
        if (diagnostic.field == field)
            result.push_back(std::move(diagnostic));
    }
    return result;
}

QVariant VariablesTableModel::data(const QModelIndex& index, int role) const
{
    const core::Variable* variable = variableAt(index.row());
    if (!variable)
        return {};
    const int column = index.column();
    switch (role) {
    case Qt::DisplayRole:
        return displayData(*variable, column);
    case Qt::EditRole:
        if (column == TypeColumn)
            return fromStd(std::string(core::iecTypeName(variable->type)));
        if (column == KindColumn)
            return kindFileName(variable->kind);
        if (column == DefaultColumn)
            return fromStd(variable->defaultValue);
        return displayData(*variable, column);
    case Qt::ToolTipRole:
        return toolTip(*variable, column);
    case Qt::BackgroundRole:
        if (core::hasErrors(diagnostics(*variable, column)))
            return QColor(220, 50, 47, 80); // reads on light and dark palettes
        return {};
    case Qt::ForegroundRole:
        if (column == DefaultColumn && variable->defaultValue.empty())
            return secondaryTextColor(QPalette(), QPalette::Base);
        return {};
    case Qt::FontRole:
        if (column == DefaultColumn && variable->defaultValue.empty()) {
            QFont font;
            font.setItalic(true);
            return font;
        }
        return {};
    default:
        return {};
    }
}

QVariant VariablesTableModel::displayData(const core::Variable& variable, int column) const
{
    switch (column) {
    case NameColumn:
        return fromStd(variable.name);
    case TypeColumn:
        return fromStd(std::string(core::iecTypeName(variable.type)));
    case KindColumn:
        return kindText(variable.kind);
    case DefaultColumn:
        // An empty default shows what the PLC starts with, greyed.
        return variable.defaultValue.empty() ? fromStd(std::string(core::implicitDefault(variable.type)))
                                             : fromStd(variable.defaultValue);
    case CommentColumn:
        return fromStd(variable.comment);
    default:
        return {};
    }
}

QVariant VariablesTableModel::toolTip(const core::Variable& variable, int column) const
{
    QStringList lines;
    for (const core::Diagnostic& diagnostic : diagnostics(variable, column))
        lines << diagnosticText(diagnostic);
    if (column == DefaultColumn && variable.defaultValue.empty())
        lines << tr("No default: the PLC starts with %1.")
                     .arg(fromStd(std::string(core::implicitDefault(variable.type))));
    if (column == CommentColumn && !variable.comment.empty())
        lines << fromStd(variable.comment);
    if (lines.isEmpty())
        return {};
    return lines.join(QLatin1Char('\n'));
}

bool VariablesTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    const core::Variable* variable = variableAt(index.row());
    if (!variable || role != Qt::EditRole)
        return false;
    const QString name = fromStd(variable->name);
    const QString text = value.toString();
    switch (index.column()) {
    case NameColumn: {
        const QString newName = text.trimmed();
        if (newName == name)
            return true;
        if (!pushEdit(index, new RenameVariableCommand(*m_document, name, newName)))
            return false;
        emit variableRenamed(name, newName);
        return true;
    }
    case TypeColumn: {
        const std::optional<core::IecType> type = core::parseIecType(text.trimmed().toStdString());
        if (!type) {
            emit editRefused(index, tr("'%1' is not a supported type: use one of %2.").arg(text, supportedTypes()));
            return false;
        }
        return pushEdit(index, new SetVariableTypeCommand(*m_document, name, *type));
    }
    case KindColumn: {
        const std::optional<core::VariableKind> kind = parseKind(text);
        if (!kind) {
            emit editRefused(index,
                tr("'%1' is not a kind: use %2, %3 or %4.")
                    .arg(text, kindText(core::VariableKind::Input), kindText(core::VariableKind::Output),
                        kindText(core::VariableKind::Internal)));
            return false;
        }
        if (*kind == variable->kind)
            return true;
        return pushEdit(index, new SetVariableKindCommand(*m_document, name, *kind));
    }
    case DefaultColumn:
        return pushEdit(index, new SetVariableDefaultCommand(*m_document, name, text.trimmed()));
    case CommentColumn:
        return pushEdit(index, new SetVariableCommentCommand(*m_document, name, text));
    default:
        return false;
    }
}

bool VariablesTableModel::pushEdit(const QModelIndex& index, QUndoCommand* command)
{
    QString failure;
    const QMetaObject::Connection connection
        = connect(m_document, &Document::editFailed, this, [&failure](const QString& message) { failure = message; });
    const bool ok = m_document->push(command);
    disconnect(connection);
    if (!ok)
        emit editRefused(index, failure);
    return ok;
}

Qt::ItemFlags VariablesTableModel::flags(const QModelIndex& index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable;
}

void VariablesTableModel::retranslate()
{
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), { Qt::DisplayRole, Qt::ToolTipRole });
}

QVariant VariablesTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation == Qt::Vertical)
        return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
    if (role == Qt::DisplayRole) {
        switch (section) {
        case NameColumn:
            return tr("Name");
        case TypeColumn:
            return tr("Type");
        case KindColumn:
            return tr("Kind");
        case DefaultColumn:
            return tr("Default");
        case CommentColumn:
            return tr("Comment");
        default:
            return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case NameColumn:
            return tr("IEC 61131-3 identifier, unique ignoring case. Renaming updates every condition.");
        case TypeColumn:
            return tr("Elementary IEC 61131-3 type");
        case KindColumn:
            return tr("Input: read from the machine. Output: written by the actions of nested GRAFCETs. Internal: a "
                      "memory the program writes and reads.");
        case DefaultColumn:
            return tr("Initial value, a literal of the type; empty for the type's implicit default");
        case CommentColumn:
            return tr("Free text, written into the generated declarations");
        default:
            return {};
        }
    }
    return {};
}

void VariablesTableModel::onVariablesChanged()
{
    const int count = static_cast<int>(m_document->model().variables().size());
    if (count == m_rowCount) {
        // Renamed or moved: the rows stay, their contents change. No reset:
        // this may run inside setData(), under an open cell editor.
        if (count > 0)
            emit dataChanged(index(0, 0), index(count - 1, ColumnCount - 1));
        return;
    }
    beginResetModel();
    m_rowCount = count;
    endResetModel();
}

void VariablesTableModel::onVariableChanged(const QString& name)
{
    const int row = rowOf(name);
    if (row >= 0)
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

void VariablesTableModel::onDiagnosticsChanged()
{
    if (m_rowCount > 0)
        emit dataChanged(index(0, 0), index(m_rowCount - 1, ColumnCount - 1), { Qt::BackgroundRole, Qt::ToolTipRole });
}

bool VariablesTableModel::parseRows(const QString& text, std::vector<core::Variable>* variables, QString* error)
{
    variables->clear();
    const QStringList lines = text.split(QLatin1Char('\n'));
    bool first = true;
    VariablePasteColumns columns;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        if (line.trimmed().isEmpty())
            continue;
        const QStringList cells = line.split(QLatin1Char('\t'));
        if (std::exchange(first, false)) {
            if (const std::optional<VariablePasteColumns> header = headerColumns(cells)) {
                columns = *header;
                continue;
            }
        }
        const auto cell = [&cells](int column) { return column >= 0 ? cells.value(column).trimmed() : QString(); };
        const QString name = cell(columns.name);
        const int lineNumber = static_cast<int>(i) + 1;
        if (name.isEmpty()) {
            *error = tr("Line %1: the name is empty.").arg(lineNumber);
            return false;
        }
        core::Variable variable;
        variable.name = name.toStdString();
        const QString typeName = cell(columns.type);
        if (!typeName.isEmpty()) {
            const std::optional<core::IecType> type = core::parseIecType(typeName.toStdString());
            if (!type) {
                *error = tr("Line %1: '%2' is not a supported type: use one of %3.")
                             .arg(lineNumber)
                             .arg(typeName, supportedTypes());
                return false;
            }
            variable.type = *type;
        }
        variable.defaultValue = cell(columns.defaultValue).toStdString();
        variable.comment = cell(columns.comment).toStdString();
        // Without a header, the kind comes after the comment, so that rows
        // without one still read; and without a header saying "Kind", a
        // fifth cell that names no kind is one of the spreadsheet's own.
        const QString kindName = cell(columns.kind);
        if (!kindName.isEmpty()) {
            const std::optional<core::VariableKind> kind = parseKind(kindName);
            if (kind) {
                variable.kind = *kind;
            } else if (columns.kindDeclared) {
                *error
                    = tr("Line %1: '%2' is not a kind: use input, output or internal.").arg(lineNumber).arg(kindName);
                return false;
            }
        }
        // Cells beyond these are ignored: spreadsheets often add some.
        variables->push_back(std::move(variable));
    }
    if (variables->empty()) {
        *error = tr("There are no variables to paste: copy rows of name, type, default and comment, separated by "
                    "tabs.");
        return false;
    }
    return true;
}

QString VariablesTableModel::formatRows(const std::vector<core::Variable>& variables)
{
    QString text = QStringLiteral("Name\tType\tDefault\tComment\tKind\n");
    for (const core::Variable& variable : variables) {
        text += cellText(variable.name) + QLatin1Char('\t') + fromStd(std::string(core::iecTypeName(variable.type)))
            + QLatin1Char('\t') + cellText(variable.defaultValue) + QLatin1Char('\t') + cellText(variable.comment)
            + QLatin1Char('\t') + kindFileName(variable.kind) + QLatin1Char('\n');
    }
    return text;
}

} // namespace editor
