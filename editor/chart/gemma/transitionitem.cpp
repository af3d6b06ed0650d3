#include "editor/chart/gemma/transitionitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/chart/layoutconversion.h"
#include "editor/chart/segmentstroke.h"
#include "editor/document.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPathStroker>
#include <QStyleOptionGraphicsItem>


namespace editor {

namespace {

QString fromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// The arrowhead at the end of the last segment, and where the line stops so
// that its end does not poke through the tip.
QPolygonF arrowHead(QPointF from, QPointF tip, QPointF* base)
{
    const QLineF segment(from, tip);
    const double length = segment.length();
    const QPointF direction = length > 0 ? (tip - from) / length : QPointF(1, 0);
    const QPointF normal(-direction.y(), direction.x());
    *base = tip - direction * chartstyle::kArrowLength;
    return QPolygonF({tip, *base + normal * chartstyle::kArrowHalfWidth, *base - normal * chartstyle::kArrowHalfWidth});
}

// The layout puts a label beside, left of, or centred on its bar; the text
// keeps to the bar's side so that short conditions stay next to it.
Qt::Alignment alignmentTowards(const QRectF& label, QPointF bar)
{
    if (label.right() <= bar.x() + 0.5)
        return Qt::AlignRight;
    if (label.left() >= bar.x() - 0.5)
        return Qt::AlignLeft;
    return Qt::AlignHCenter;
}

} // namespace

TransitionItem::TransitionItem(const Document& document, const core::TransitionLayout& layout,
                               QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_document(document)
    , m_id(QString::fromStdString(layout.id))
    , m_sourceId(fromView(layout.source))
    , m_targetId(fromView(layout.target))
    , m_modelId(layout.id)
    , m_barCenter(toQPointF(layout.barCenter))
    , m_barHorizontal(layout.barHorizontal)
    , m_labelRect(toQRectF(layout.labelRect))
{
    setFlag(ItemIsSelectable);
    setZValue(chartstyle::kTransitionZ);

    for (const core::Point& point : layout.route)
        m_line << toQPointF(point);
    if (m_line.size() >= 2) {
        QPointF base;
        m_arrow = arrowHead(m_line[m_line.size() - 2], m_line.last(), &base);
        m_line.last() = base;
    }
    m_labelAlignment = alignmentTowards(m_labelRect, m_barCenter);

    const double margin = chartstyle::kHaloWidth + chartstyle::kBarWidth;
    m_bounds = (m_line.boundingRect() | m_arrow.boundingRect() | m_labelRect)
                   .adjusted(-margin, -margin, margin, margin);
}

QVariant TransitionItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemSelectedHasChanged)
        setZValue(value.toBool() ? chartstyle::kSelectedZ : chartstyle::kTransitionZ);
    return QGraphicsItem::itemChange(change, value);
}

bool TransitionItem::isHiddenInModel() const
{
    return !m_document.model().isEffective(m_modelId);
}

void TransitionItem::refresh()
{
    updateLabel();
    m_shapeValid = false;
    update();
}

void TransitionItem::setProblemMark(bool problem)
{
    if (m_problem == problem)
        return;
    m_problem = problem;
    update();
}

void TransitionItem::setFired(bool fired)
{
    if (m_fired == fired)
        return;
    m_fired = fired;
    update();
}

void TransitionItem::setTokenMarks(const QList<bool>& tokens)
{
    if (m_tokens == tokens)
        return;
    m_tokens = tokens;
    update();
}

void TransitionItem::setNoteNumber(int number)
{
    if (m_noteNumber == number)
        return;
    m_noteNumber = number;
    refresh();
}

void TransitionItem::updateLabel()
{
    const core::Model& model = m_document.model();
    const core::Transition* transition = model.transition(m_modelId);
    if (!transition)
        return;
    const int priority = model.priority(m_modelId);
    const bool choice = model.effectiveOutgoing(transition->source).size() > 1;
    // The overline that marks a negated transition lives on the priority, so
    // a negated transition shows its priority even when it has no siblings.
    const bool showPriority = priority > 0 && (choice || transition->negated);

    m_priorityText = showPriority ? QString::number(priority) : QString();
    m_overlined = transition->negated;
    m_conditionText = QString::fromStdString(transition->condition).simplified();
    m_separator = showPriority && !m_conditionText.isEmpty() ? QStringLiteral(": ") : QString();

    // Each measurement shapes its text anew: none twice for the same text (a
    // label is often its priority alone).
    const QString prefix = m_priorityText + m_separator;
    const double badgePadding = priorityOverlined() ? 2 * chartstyle::kNegatedBadgePadding : 0.0;
    const double prefixWidth = (prefix.isEmpty() ? 0.0 : chartstyle::advance(prefix)) + badgePadding;
    m_elidedCondition.clear();
    if (!m_conditionText.isEmpty()) {
        const QFontMetricsF metrics(chartstyle::font());
        const double room = std::max(0.0, m_labelRect.width() - prefixWidth);
        m_elidedCondition = metrics.elidedText(m_conditionText, Qt::ElideRight, room);
        m_conditionCut = m_elidedCondition != m_conditionText;
        if (m_conditionCut && m_noteNumber > 0) {
            const QString marker = QStringLiteral("[%1]").arg(m_noteNumber);
            const QString start =
                metrics.elidedText(m_conditionText, Qt::ElideRight, std::max(0.0, room - metrics.horizontalAdvance(marker)));
            // An ellipsis alone says nothing: then the marker stands for the whole condition.
            m_elidedCondition = (start.size() > 1 ? start : QString()) + marker;
        }
    } else {
        m_conditionCut = false;
    }
    m_priorityWidth = m_separator.isEmpty() ? prefixWidth - badgePadding : chartstyle::advance(m_priorityText);
    m_shownWidth = m_elidedCondition.isEmpty() ? prefixWidth
                                               : chartstyle::advance(prefix + m_elidedCondition) + badgePadding;
}

QString TransitionItem::labelText() const
{
    return m_priorityText + m_separator + m_conditionText;
}

QRectF TransitionItem::labelTextRect() const
{
    const double width = std::min(m_labelRect.width(), m_shownWidth);
    double x = m_labelRect.left();
    if (m_labelAlignment == Qt::AlignRight)
        x = m_labelRect.right() - width;
    else if (m_labelAlignment == Qt::AlignHCenter)
        x = m_labelRect.center().x() - width / 2;
    return {x, m_labelRect.top(), width, m_labelRect.height()};
}

QRectF TransitionItem::priorityRect() const
{
    if (!priorityShown())
        return {};
    const QFontMetricsF metrics(chartstyle::font());
    const QRectF text = labelTextRect();
    const double baseline = text.center().y() + (metrics.ascent() - metrics.descent()) / 2;
    if (!priorityOverlined())
        return {text.left(), baseline - metrics.ascent(), m_priorityWidth, metrics.height()};
    const double padding = chartstyle::kNegatedBadgePadding;
    const double top = baseline - metrics.capHeight() - chartstyle::kOverlineGap - chartstyle::kOverlineWidth - padding;
    const double bottom = baseline + padding;
    return {text.left(), top, m_priorityWidth + 2 * padding, bottom - top};
}

QLineF TransitionItem::barLine() const
{
    const double half = core::kTransitionBarLength / 2;
    if (m_barHorizontal)
        return {m_barCenter.x() - half, m_barCenter.y(), m_barCenter.x() + half, m_barCenter.y()};
    return {m_barCenter.x(), m_barCenter.y() - half, m_barCenter.x(), m_barCenter.y() + half};
}

QPainterPath TransitionItem::buildShape() const
{
    QPainterPath route;
    route.addPolygon(m_line);
    QPainterPathStroker stroker;
    stroker.setWidth(8);
    QPainterPath shape = stroker.createStroke(route);
    shape.addPolygon(m_arrow);
    const QLineF bar = barLine();
    shape.addRect(QRectF(bar.p1(), bar.p2()).adjusted(-4, -4, 4, 4));
    if (!labelText().isEmpty())
        shape.addRect(labelTextRect());
    shape.setFillRule(Qt::WindingFill);
    return shape;
}

QString TransitionItem::toolTipText() const
{
    const core::Model& model = m_document.model();
    const core::Transition* transition = model.transition(m_modelId);
    if (!transition)
        return {};
    QString text = QStringLiteral("<b>%1 → %2</b>").arg(m_sourceId, m_targetId);
    if (transition->isFamilyTransition())
        text += QStringLiteral("<br/>") + tr("Family transition: applies to every F state").toHtmlEscaped();
    const int priority = model.priority(m_modelId);
    QString status = priority > 0 ? tr("Priority %1").arg(priority) : tr("Not effective (hidden)");
    if (transition->negated)
        status = tr("%1, negated").arg(status);
    text += QStringLiteral("<br/>") + status.toHtmlEscaped();
    const QString condition = QString::fromStdString(transition->condition).trimmed();
    text += QStringLiteral("<br/>") + tr("Condition:").toHtmlEscaped() + QLatin1Char(' ')
          + (condition.isEmpty() ? QStringLiteral("<i>%1</i>").arg(tr("empty").toHtmlEscaped())
                                 : QStringLiteral("<tt>%1</tt>").arg(condition.toHtmlEscaped()));
    if (!transition->tokens.empty()) {
        QStringList tokens;
        for (const std::string& token : transition->tokens)
            tokens << QString::fromStdString(token);
        text += QStringLiteral("<br/>") + tr("Tokens: %1").arg(tokens.join(QStringLiteral(", "))).toHtmlEscaped();
    }
    return text;
}

QRectF TransitionItem::boundingRect() const
{
    return m_bounds;
}

QPainterPath TransitionItem::shape() const
{
    if (!m_shapeValid) {
        m_shape = buildShape();
        m_shapeValid = true;
    }
    return m_shape;
}

void TransitionItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const bool hidden = isHiddenInModel();
    const QLineF bar = barLine();

    if (option->state & QStyle::State_Selected) {
        QPen halo(chartstyle::haloColor(), chartstyle::kHaloWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
        painter->setPen(halo);
        painter->setBrush(Qt::NoBrush);
        painter->drawPolyline(m_line);
        painter->drawPolygon(m_arrow);
        painter->drawLine(bar);
        if (!labelText().isEmpty())
            painter->drawRoundedRect(labelTextRect().adjusted(-2, -1, 2, 1), 3, 3);
    }

    const QColor ink = m_fired ? chartstyle::firedColor() : chartstyle::inkColor();
    QPen pen(ink, m_fired ? chartstyle::kFiredWidth : chartstyle::kRouteWidth,
             hidden ? Qt::DashLine : Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin);
    painter->setPen(pen);
    painter->setBrush(Qt::NoBrush);
    segmentstroke::drawPolyline(painter, m_line);
    pen.setStyle(Qt::SolidLine);
    painter->setPen(pen);
    painter->setBrush(ink);
    painter->drawPolygon(m_arrow);

    const QColor mark = m_problem ? chartstyle::problemColor() : ink;
    painter->setPen(QPen(mark, chartstyle::kBarWidth, Qt::SolidLine, Qt::FlatCap));
    painter->drawLine(bar);

    paintTokens(painter);
    paintLabel(painter);
}

// Evenly along the bar, which is 20 units long: a token reads as a memory
// sitting on its transition.
void TransitionItem::paintTokens(QPainter* painter) const
{
    if (m_tokens.isEmpty())
        return;
    const QLineF bar = barLine();
    const double count = static_cast<double>(m_tokens.size());
    painter->setPen(QPen(chartstyle::inkColor(), 1.2));
    for (qsizetype i = 0; i < m_tokens.size(); ++i) {
        const QPointF center = bar.pointAt((static_cast<double>(i) + 0.5) / count);
        painter->setBrush(m_tokens[i] ? chartstyle::trueMarkColor() : QColor(Qt::white));
        painter->drawEllipse(center, chartstyle::kTokenRadius, chartstyle::kTokenRadius);
    }
}

void TransitionItem::paintLabel(QPainter* painter) const
{
    if (m_priorityText.isEmpty() && m_elidedCondition.isEmpty())
        return;
    const QFontMetricsF metrics(chartstyle::font());
    const QRectF textRect = labelTextRect();
    const double baseline = textRect.center().y() + (metrics.ascent() - metrics.descent()) / 2;
    QPointF at(textRect.left(), baseline);

    const QColor color = m_problem ? chartstyle::problemColor() : chartstyle::labelColor();
    painter->setPen(color);
    painter->setFont(chartstyle::font());
    if (priorityOverlined()) {
        // Light on a dark badge, overline included: a negated transition
        // stands out at fitted zoom, where a plain overline is a stray pixel.
        const QRectF badge = priorityRect();
        painter->setPen(Qt::NoPen);
        painter->setBrush(color);
        painter->drawRoundedRect(badge, 2.5, 2.5);
        const QColor light = chartstyle::stepFillColor();
        const double x = badge.left() + chartstyle::kNegatedBadgePadding;
        painter->setPen(light);
        painter->drawText(QPointF(x, baseline), m_priorityText);
        // Drawn rather than QFont::setOverline: the font's overline is a
        // hairline that vanishes when the sheet is fitted to a screen.
        const double y = baseline - metrics.capHeight() - chartstyle::kOverlineGap;
        painter->setPen(QPen(light, chartstyle::kOverlineWidth, Qt::SolidLine, Qt::FlatCap));
        painter->drawLine(QLineF(x, y, x + m_priorityWidth, y));
        painter->setPen(color);
        at.rx() = badge.right();
    } else if (!m_priorityText.isEmpty()) {
        painter->drawText(at, m_priorityText);
        at.rx() += m_priorityWidth;
    }
    painter->drawText(at, m_separator + m_elidedCondition);
}

} // namespace editor
