#pragma once

#include <QWidget>

class QLabel;
class QPushButton;

namespace editor {

class WrappingLabel;

// What the Step dock shows while nothing is selected: what the chart is
// and the four moves that make a model (hide what the machine does not
// need, declare the variables, write the conditions, simulate, verify and
// export), with a way into an example and the user guide. A first start
// explains itself there, in the space a selection fills later.
class StartGuide : public QWidget {
    Q_OBJECT

public:
    explicit StartGuide(QWidget* parent = nullptr);

    QPushButton* exampleButton() const { return m_exampleButton; }
    QPushButton* userGuideButton() const { return m_userGuideButton; }

signals:
    // The first shipped example (File > Examples has them all).
    void exampleRequested();
    void userGuideRequested();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();

    QLabel* m_title;
    WrappingLabel* m_text;
    QPushButton* m_exampleButton;
    QPushButton* m_userGuideButton;
};

} // namespace editor
