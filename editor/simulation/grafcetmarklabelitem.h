#pragma once

#include <QGraphicsItem>
#include <QString>

namespace editor {

// A text the simulation marks put on a nested GRAFCET (GrafcetSimulationMarks):
// a running timer's elapsed and preset time under the receptivity that reads
// it, or the caption above the drawing that says whether the GRAFCET runs.
// Drawn in a small rounded box above every other item, so that it stays
// readable wherever it stands. Its position is its box's top-left corner.
class GrafcetMarkLabelItem : public QGraphicsItem {
public:
    enum { Type = QGraphicsItem::UserType + 20 };
    enum class Kind { Timer, Caption };
    // Neutral: a frozen GRAFCET; Running: it runs, or a timer counts;
    // Elapsed: a timer reached its preset; Warning: Unstable.
    enum class Tone { Neutral, Running, Elapsed, Warning };

    explicit GrafcetMarkLabelItem(Kind kind, QGraphicsItem* parent = nullptr);

    int type() const override { return Type; }
    Kind kind() const { return m_kind; }
    const QString& text() const { return m_text; }
    Tone tone() const { return m_tone; }
    void setText(const QString& text, Tone tone);
    // The transition whose receptivity reads the timer (Timer only).
    int transition() const { return m_transition; }
    void setTransition(int number) { m_transition = number; }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    double scale() const;

    Kind m_kind;
    Tone m_tone = Tone::Neutral;
    QString m_text;
    int m_transition = 0;
    QRectF m_box;
};

} // namespace editor
