#pragma once

// One component of the Machine tab: a fixed cell with the component's name
// and kind, a drawing of its state (each kind's subclass draws it), and a
// line per role naming the wired variable, its lamp lit while the variable
// is TRUE. The item keeps only its component's index: it reads the machine
// and the signals from its MachineScene when it paints, and asks for a
// repaint only when what it shows changed (refresh()), so a frame of a fast
// simulation repaints the components that moved and nothing else.

#include <QColor>
#include <QCoreApplication>
#include <QGraphicsItem>
#include <QRectF>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace core::machine {
struct Component;
}

namespace editor {

class MachineScene;

// How finely a moving part's position (0..1) counts in a look: finer than a
// pixel of a rod's or a belt's travel, so a visible move always repaints.
inline constexpr double kLookPositionSteps = 200;

class MachineComponentItem : public QGraphicsItem {
    Q_DECLARE_TR_FUNCTIONS(MachineComponentItem)

public:
    enum { Type = UserType + 60 };

    MachineComponentItem(MachineScene& scene, std::size_t component, const QRectF& cell);

    int type() const override { return Type; }
    QRectF boundingRect() const override { return m_cell; }
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

    std::size_t component() const { return m_component; }
    // Repaints when the look changed since the last paint request; true then.
    bool refresh();
    // What the item shows, as numbers: equal looks paint the same.
    std::vector<std::int64_t> look() const;
    // The text of each role line ("extended: Clamped"), in the kind's role order.
    QStringList roleLines() const;

    // The colours the drawings share, readable on light and dark backgrounds.
    static QColor litColour();
    static QColor unlitColour();

protected:
    // Right-click: the faults of the component's sensors, and a jam for a
    // cylinder or a conveyor (docs/simulation.md, "Faults").
    void contextMenuEvent(QGraphicsSceneContextMenuEvent* event) override;

protected:
    const core::machine::Component& componentDescription() const;
    MachineScene& machineScene() const { return m_scene; }
    bool signal(std::size_t role) const;
    QRectF bodyRect() const;
    // The drawing of the kind in `body`; `ink` is the palette's text colour.
    virtual void paintBody(QPainter& painter, const QRectF& body, const QColor& ink) const = 0;
    // What the drawing shows beyond the role signals (a position, parts).
    virtual void appendLook(std::vector<std::int64_t>& look) const;

    static void paintLamp(QPainter& painter, const QPointF& centre, double radius, bool lit);
    // A faulted sensor's lamp: struck through in the problem colour.
    static void strikeLamp(QPainter& painter, const QPointF& centre, double radius);

private:
    void paintRoles(QPainter& painter, const QColor& ink) const;

    MachineScene& m_scene;
    std::size_t m_component;
    QRectF m_cell;
    std::vector<std::int64_t> m_look;
};

} // namespace editor
