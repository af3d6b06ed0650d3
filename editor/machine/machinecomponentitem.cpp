#include "editor/machine/machinecomponentitem.h"

#include "editor/chart/chartstyle.h"
#include "editor/machine/machinelayout.h"
#include "editor/machine/machinescene.h"
#include "editor/machine/machinetext.h"
#include "editor/simulation/faultmenu.h"
#include "editor/simulation/simulationsession.h"

#include "core/machine/machine.h"

#include <QFontMetricsF>
#include <QGraphicsSceneContextMenuEvent>
#include <QMenu>
#include <QPainter>
#include <QPalette>

namespace editor {

MachineComponentItem::MachineComponentItem(MachineScene& scene, std::size_t component, const QRectF& cell)
    : m_scene(scene)
    , m_component(component)
    , m_cell(cell)
{
    const core::machine::Component& description = componentDescription();
    setToolTip(QStringLiteral("%1 (%2)\n%3")
                   .arg(QString::fromStdString(description.name), machinetext::kindName(description.kind),
                        roleLines().join(QLatin1Char('\n'))));
}

QColor MachineComponentItem::litColour()
{
    return QColor(0x2e, 0xc4, 0x5a);
}

QColor MachineComponentItem::unlitColour()
{
    return QColor(0x6b, 0x72, 0x7c);
}

const core::machine::Component& MachineComponentItem::componentDescription() const
{
    return m_scene.machine().components[m_component];
}

bool MachineComponentItem::signal(std::size_t role) const
{
    return m_scene.signal(m_component, role);
}

QRectF MachineComponentItem::bodyRect() const
{
    using namespace machinelayout;
    return QRectF(m_cell.left() + kPadding, m_cell.top() + kPadding + kHeaderHeight, m_cell.width() - 2 * kPadding,
                  bodyHeight(componentDescription().kind));
}

std::vector<std::int64_t> MachineComponentItem::look() const
{
    std::vector<std::int64_t> now;
    const std::size_t roles = core::machine::kindSpec(componentDescription().kind).roles.size();
    for (std::size_t role = 0; role < roles; ++role) {
        now.push_back(signal(role) ? 1 : 0);
        now.push_back(static_cast<std::int64_t>(m_scene.sensorFault(m_component, role)));
    }
    now.push_back(m_scene.jammed(m_component) ? 1 : 0);
    appendLook(now);
    return now;
}

void MachineComponentItem::appendLook(std::vector<std::int64_t>&) const {}

bool MachineComponentItem::refresh()
{
    std::vector<std::int64_t> now = look();
    if (now == m_look)
        return false;
    m_look = std::move(now);
    update();
    return true;
}

QStringList MachineComponentItem::roleLines() const
{
    const core::machine::Component& description = componentDescription();
    const core::machine::ComponentKindSpec& spec = core::machine::kindSpec(description.kind);
    QStringList lines;
    for (std::size_t role = 0; role < spec.roles.size(); ++role) {
        const std::string& wire = role < description.wires.size() ? description.wires[role] : std::string();
        //: %1: a role of a machine component ("extended"); %2: the variable wired to it
        lines << tr("%1: %2").arg(machinetext::roleName(spec.roles[role].key),
                                  wire.empty() ? tr("(not wired)") : QString::fromStdString(wire));
    }
    return lines;
}

void MachineComponentItem::paintLamp(QPainter& painter, const QPointF& centre, double radius, bool lit)
{
    const QColor colour = lit ? litColour() : unlitColour();
    painter.setPen(QPen(colour.darker(150), 1));
    painter.setBrush(lit ? colour : colour.lighter(130));
    painter.drawEllipse(centre, radius, radius);
}

void MachineComponentItem::strikeLamp(QPainter& painter, const QPointF& centre, double radius)
{
    painter.setPen(QPen(chartstyle::problemColor(), 2));
    const QPointF corner(radius + 2, radius + 2);
    painter.drawLine(centre - QPointF(corner.x(), -corner.y()), centre + QPointF(corner.x(), -corner.y()));
}

void MachineComponentItem::contextMenuEvent(QGraphicsSceneContextMenuEvent* event)
{
    SimulationSession* session = m_scene.session();
    if (!m_scene.showsSimulation() || !session || !session->hasMachine()) {
        event->ignore();
        return;
    }
    const core::machine::Component& description = componentDescription();
    const core::machine::ComponentKindSpec& spec = core::machine::kindSpec(description.kind);
    QWidget* parent = event->widget();
    QMenu menu(parent);
    for (std::size_t role = 0; role < spec.roles.size() && role < description.wires.size(); ++role) {
        if (spec.roles[role].direction == core::machine::SignalDirection::Sensor && !description.wires[role].empty())
            addSensorFaultActions(menu, *session, QString::fromStdString(description.wires[role]), parent);
    }
    if (core::machine::canJam(description.kind))
        addJamActions(menu, *session, QString::fromStdString(description.name), m_scene.jammed(m_component), parent);
    if (menu.isEmpty()) {
        event->ignore();
        return;
    }
    menu.exec(event->screenPos());
    event->accept();
}

void MachineComponentItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    m_look = look();
    const QPalette palette = m_scene.palette();
    const QColor ink = palette.color(QPalette::Text);
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(palette.color(QPalette::Mid), 1));
    painter->setBrush(palette.color(QPalette::Base));
    painter->drawRoundedRect(m_cell.adjusted(0.5, 0.5, -0.5, -0.5), 5, 5);

    const core::machine::Component& description = componentDescription();
    const QRectF header(m_cell.left() + machinelayout::kPadding, m_cell.top() + machinelayout::kPadding,
                        m_cell.width() - 2 * machinelayout::kPadding, machinelayout::kHeaderHeight);
    QFont bold = painter->font();
    bold.setBold(true);
    painter->setFont(bold);
    painter->setPen(ink);
    const QFontMetricsF boldMetrics(bold);
    painter->drawText(header.adjusted(0, 0, 0, -header.height() / 2), Qt::AlignLeft | Qt::AlignVCenter,
                      boldMetrics.elidedText(QString::fromStdString(description.name), Qt::ElideRight, header.width()));
    QFont plain = bold;
    plain.setBold(false);
    painter->setFont(plain);
    const bool isJammed = m_scene.jammed(m_component);
    painter->setPen(isJammed ? chartstyle::problemColor() : palette.color(QPalette::PlaceholderText));
    //: %1: the kind of a machine component ("Double-acting cylinder"), which a fault has stopped
    const QString kind = isJammed ? tr("%1, jammed").arg(machinetext::kindName(description.kind))
                                  : machinetext::kindName(description.kind);
    painter->drawText(header.adjusted(0, header.height() / 2, 0, 0), Qt::AlignLeft | Qt::AlignVCenter,
                      QFontMetricsF(plain).elidedText(kind, Qt::ElideRight, header.width()));

    painter->save();
    paintBody(*painter, bodyRect(), ink);
    painter->restore();
    paintRoles(*painter, ink);
}

// A line per role: its lamp, then "role: Variable".
void MachineComponentItem::paintRoles(QPainter& painter, const QColor& ink) const
{
    const QStringList lines = roleLines();
    const QRectF body = bodyRect();
    const QFontMetricsF metrics(painter.font());
    double top = body.bottom();
    for (int role = 0; role < lines.size(); ++role) {
        const QRectF line(body.left(), top, body.width(), machinelayout::kRoleLineHeight);
        const double radius = 4.5;
        const QPointF lamp(line.left() + radius + 1, line.center().y());
        paintLamp(painter, lamp, radius, signal(static_cast<std::size_t>(role)));
        const QRectF text = line.adjusted(2 * radius + 6, 0, 0, 0);
        const QString fault = sensorFaultShortText(m_scene.sensorFault(m_component, static_cast<std::size_t>(role)));
        QString shown = lines[role];
        if (!fault.isEmpty()) {
            strikeLamp(painter, lamp, radius);
            // The variable and its fault: the role is in the tooltip, the line is narrow.
            const std::string& wire = componentDescription().wires[static_cast<std::size_t>(role)];
            //: %1: a sensor variable ("Clamped"); %2: its fault ("stuck FALSE")
            shown = tr("%1: %2").arg(QString::fromStdString(wire), fault);
        }
        painter.setPen(fault.isEmpty() ? ink : chartstyle::problemColor());
        painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter,
                         metrics.elidedText(shown, Qt::ElideRight, text.width()));
        top += machinelayout::kRoleLineHeight;
    }
}

} // namespace editor
