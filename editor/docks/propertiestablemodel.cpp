#include "editor/docks/propertiestablemodel.h"

#include "editor/commands/propertycommands.h"
#include "editor/document.h"
#include "editor/style/severityicon.h"
#include "editor/text/displaytext.h"
#include "editor/text/propertyproblemtext.h"

#include "core/model/model.h"

namespace editor {

PropertiesTableModel::PropertiesTableModel(Document* document, QObject* parent)
    : QAbstractTableModel(parent)
    , m_document(document)
{
    reload();
}

int PropertiesTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_document->model().properties().size());
}

int PropertiesTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant PropertiesTableModel::data(const QModelIndex& index, int role) const
{
    const auto& properties = m_document->model().properties();
    if (!index.isValid() || index.row() >= static_cast<int>(properties.size()))
        return {};
    const core::UserProperty& property = properties[static_cast<std::size_t>(index.row())];
    const std::vector<core::PropertyProblem>& wrong = problems(index.row());
    switch (role) {
    case Qt::DisplayRole:
        // Cut before the view lays it out: a text of megabytes would freeze
        // it. The editor under the table holds the whole property.
        return elidedText(QString::fromStdString(index.column() == TextColumn ? property.text : property.comment));
    case Qt::EditRole:
        return QString::fromStdString(index.column() == TextColumn ? property.text : property.comment);
    case Qt::DecorationRole:
        if (index.column() == TextColumn && !wrong.empty())
            return severityIcon(core::Severity::Error);
        return {};
    case Qt::ToolTipRole:
        if (index.column() == TextColumn && !wrong.empty())
            return boundedToolTip(propertyProblemText(wrong.front()));
        return {};
    default: return {};
    }
}

QVariant PropertiesTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole)
        return {};
    if (orientation == Qt::Vertical)
        return section + 1;
    return section == TextColumn ? tr("Property") : tr("Comment");
}

Qt::ItemFlags PropertiesTableModel::flags(const QModelIndex& index) const
{
    return QAbstractTableModel::flags(index) | (index.isValid() ? Qt::ItemIsEditable : Qt::NoItemFlags);
}

bool PropertiesTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || role != Qt::EditRole)
        return false;
    const QString text = value.toString();
    if (index.column() == TextColumn)
        return m_document->push(new SetPropertyTextCommand(*m_document, index.row(), text));
    return m_document->push(new SetPropertyCommentCommand(*m_document, index.row(), text));
}

const std::vector<core::PropertyProblem>& PropertiesTableModel::problems(int row) const
{
    static const std::vector<core::PropertyProblem> none;
    return row >= 0 && row < static_cast<int>(m_problems.size()) ? m_problems[static_cast<std::size_t>(row)] : none;
}

void PropertiesTableModel::reload()
{
    beginResetModel();
    m_problems.clear();
    for (const core::UserProperty& property : m_document->model().properties())
        m_problems.push_back(problemsOf(property.text));
    endResetModel();
}

void PropertiesTableModel::recheck()
{
    const auto& properties = m_document->model().properties();
    if (properties.size() != m_problems.size()) {
        reload();
        return;
    }
    for (std::size_t row = 0; row < properties.size(); ++row) {
        m_problems[row] = problemsOf(properties[row].text);
    }
    if (!properties.empty())
        emit dataChanged(index(0, 0), index(static_cast<int>(properties.size()) - 1, ColumnCount - 1));
}

void PropertiesTableModel::setFaultAtoms(bool faulted)
{
    if (faulted == m_atoms.faulted)
        return;
    m_atoms.faulted = faulted;
    recheck();
}

// Only a GEMMA model with a machine verifies with faults: the template's own
// check otherwise.
std::vector<core::PropertyProblem> PropertiesTableModel::problemsOf(const std::string& text) const
{
    if (m_atoms.faulted)
        return core::checkProperty(m_document->model(), text, m_atoms);
    return core::checkProperty(m_document->model(), text);
}

} // namespace editor
