#include "editor/docks/grafcetactionsmodel.h"

#include "editor/chart/chartstyle.h"
#include "editor/commands/setgrafcetactioncommand.h"
#include "editor/docks/grafcetactionparts.h"
#include "editor/document.h"
#include "editor/text/conditionerrortext.h"
#include "editor/text/diagnostictext.h"

#include "core/condition/actionparser.h"
#include "core/model/model.h"

namespace editor {

GrafcetActionsModel::GrafcetActionsModel(Document* document, QObject* parent)
    : QAbstractTableModel(parent)
    , m_document(document)
{
    connect(m_document, &Document::grafcetChanged, this, [this](const QString& stepId) {
        if (stepId == m_stepId)
            refresh();
    });
    connect(m_document, &Document::modelReset, this, [this] {
        m_setParts.clear();
        refresh();
    });
    connect(m_document, &Document::diagnosticsChanged, this, &GrafcetActionsModel::refresh);
}

void GrafcetActionsModel::setStep(const QString& stepId, int number)
{
    if (stepId == m_stepId && number == m_number) {
        refresh();
        return;
    }
    beginResetModel();
    m_stepId = stepId;
    m_number = number;
    const core::GrafcetStep* shown = step();
    m_rowCount = shown ? static_cast<int>(shown->actions.size()) : 0;
    endResetModel();
}

const core::GrafcetStep* GrafcetActionsModel::step() const
{
    const core::Grafcet* grafcet = m_document->model().grafcet(m_stepId.toStdString());
    return grafcet ? grafcet->step(m_number) : nullptr;
}

// Rows added or removed reset the table; edits of the same rows only
// repaint it, so that the current cell stays where the user is.
void GrafcetActionsModel::refresh()
{
    const core::GrafcetStep* shown = step();
    const int rows = shown ? static_cast<int>(shown->actions.size()) : 0;
    if (rows != m_rowCount) {
        beginResetModel();
        m_rowCount = rows;
        endResetModel();
    } else if (rows > 0) {
        emit dataChanged(index(0, 0), index(rows - 1, ColumnCount - 1));
    }
}

int GrafcetActionsModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_rowCount;
}

int GrafcetActionsModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant GrafcetActionsModel::data(const QModelIndex& index, int role) const
{
    const core::GrafcetStep* shown = step();
    if (!shown || !index.isValid() || index.row() >= static_cast<int>(shown->actions.size()))
        return {};
    const core::GrafcetAction& action = shown->actions[static_cast<std::size_t>(index.row())];
    const GrafcetActionParts parts = this->parts(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        switch (index.column()) {
        case TimingColumn: return role == Qt::EditRole ? timingValue(parts.timing) : timingText(parts.timing);
        case QualifierColumn: return GrafcetActionParts::qualifierText(parts.qualifier);
        case VariableColumn: return parts.variable;
        case OperandColumn: return parts.operand;
        default: return {};
        }
    case Qt::ForegroundRole:
        return problemText(index.row()).isEmpty() ? QVariant() : QVariant(chartstyle::problemColor());
    case Qt::ToolTipRole: {
        const QString problems = problemText(index.row());
        return problems.isEmpty() ? QString::fromStdString(action.text) : problems;
    }
    default:
        return {};
    }
}

bool GrafcetActionsModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (role != Qt::EditRole || !index.isValid() || index.row() >= m_rowCount)
        return false;
    const GrafcetActionParts parts = editedParts(index.row(), index.column(), value.toString());
    const core::GrafcetAction action = parts.action();
    QString failure;
    const QMetaObject::Connection connection
        = connect(m_document, &Document::editFailed, this, [&failure](const QString& message) { failure = message; });
    const bool ok = m_document->push(new SetGrafcetActionCommand(*m_document, m_stepId, m_number, index.row(), action));
    disconnect(connection);
    if (!ok) {
        emit editRefused(failure);
        return false;
    }
    // Kept even when the action did not change: a qualifier chosen for an
    // action without variable yet changes no text (maybe not even the timing).
    m_setParts[{m_stepId, m_number, index.row()}] = parts;
    emit dataChanged(this->index(index.row(), 0), this->index(index.row(), ColumnCount - 1));
    return true;
}

GrafcetActionParts GrafcetActionsModel::parts(int row) const
{
    const core::GrafcetStep* shown = step();
    if (!shown || row < 0 || row >= static_cast<int>(shown->actions.size()))
        return {};
    const core::GrafcetAction& action = shown->actions[static_cast<std::size_t>(row)];
    const auto set = m_setParts.find({m_stepId, m_number, row});
    if (set != m_setParts.end() && set->second.action() == action)
        return set->second;
    return GrafcetActionParts::of(action);
}

core::GrafcetAction GrafcetActionsModel::editedAction(int row, int column, const QString& value) const
{
    return editedParts(row, column, value).action();
}

GrafcetActionParts GrafcetActionsModel::editedParts(int row, int column, const QString& value) const
{
    const core::GrafcetStep* shown = step();
    if (!shown || row < 0 || row >= static_cast<int>(shown->actions.size()))
        return {};
    GrafcetActionParts parts = this->parts(row);
    switch (column) {
    case TimingColumn:
        if (core::ActionTiming timing; parseTiming(value, &timing))
            parts.setTiming(timing);
        break;
    case QualifierColumn:
        if (GrafcetActionParts::Qualifier qualifier; GrafcetActionParts::parseQualifier(value, &qualifier))
            parts.setQualifier(qualifier);
        break;
    case VariableColumn: parts.variable = value.trimmed(); break;
    case OperandColumn: parts.operand = value.trimmed(); break;
    default: break;
    }
    return parts;
}

QString GrafcetActionsModel::syntaxProblem(const core::GrafcetAction& action)
{
    const core::cond::ActionParseResult parsed = core::cond::parseAction(action.text);
    return parsed.ok() ? QString() : conditionErrorText(*parsed.error);
}

QString GrafcetActionsModel::problemText(int row) const
{
    QStringList lines;
    for (const core::Diagnostic& diagnostic : m_document->diagnosticsFor(ElementRef::grafcetStep(m_stepId, m_number))) {
        if (diagnostic.field == "action" && diagnostic.actionIndex == row && diagnostic.severity != core::Severity::Info)
            lines << diagnosticText(diagnostic);
    }
    return lines.join(QLatin1Char('\n'));
}

Qt::ItemFlags GrafcetActionsModel::flags(const QModelIndex& index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable;
}

QVariant GrafcetActionsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation == Qt::Vertical)
        return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
    if (role == Qt::DisplayRole) {
        switch (section) {
        case TimingColumn: return tr("When");
        //: short: the column is narrow; its tooltip says "qualifier" in full
        case QualifierColumn: return tr("Qual.");
        case VariableColumn: return tr("Variable");
        //: the condition after IF of an N action, or the value of a := action; short: the column is narrow
        case OperandColumn: return tr("IF / value");
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case TimingColumn: return tr("While the step is active (N), or once when it is activated or deactivated "
                                     "(S, R, :=)");
        case QualifierColumn: return tr("Qualifier. N: the variable is TRUE while the step is active\nS, R: set it "
                                        "TRUE or FALSE\n:=: assign it the value");
        case VariableColumn: return tr("An output or internal variable, or Complete");
        case OperandColumn: return tr("N: only IF this condition holds (may be empty)\n:=: the value assigned");
        default: return {};
        }
    }
    return {};
}

void GrafcetActionsModel::retranslate()
{
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    refresh();
}

QString GrafcetActionsModel::timingText(core::ActionTiming timing)
{
    switch (timing) {
    case core::ActionTiming::Continuous: return tr("While active");
    case core::ActionTiming::OnActivation: return tr("On activation");
    case core::ActionTiming::OnDeactivation: return tr("On deactivation");
    }
    return {};
}

QString GrafcetActionsModel::timingValue(core::ActionTiming timing)
{
    switch (timing) {
    case core::ActionTiming::Continuous: return QStringLiteral("continuous");
    case core::ActionTiming::OnActivation: return QStringLiteral("activation");
    case core::ActionTiming::OnDeactivation: return QStringLiteral("deactivation");
    }
    return {};
}

bool GrafcetActionsModel::parseTiming(const QString& value, core::ActionTiming* timing)
{
    for (core::ActionTiming candidate : {core::ActionTiming::Continuous, core::ActionTiming::OnActivation,
                                         core::ActionTiming::OnDeactivation}) {
        if (value == timingValue(candidate) || value == timingText(candidate)) {
            *timing = candidate;
            return true;
        }
    }
    return false;
}

} // namespace editor
