#pragma once

#include <QWidget>

namespace editor {

// A BOOL the program writes, shown as a signal lamp: a round light, lit
// green for TRUE, dark grey for FALSE. Read only: it takes no focus and no
// clicks, unlike the input toggles beside it.
class LampIndicator : public QWidget {
    Q_OBJECT

public:
    explicit LampIndicator(QWidget* parent = nullptr);

    bool isOn() const { return m_on; }
    void setOn(bool on);
    // The lamp's colours: lit, and off.
    static QColor onColour();
    static QColor offColour();

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    bool m_on = false;
};

} // namespace editor
