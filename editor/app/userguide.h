#pragma once

// Help > User Guide: the user documentation (docs/user-guide.md and the
// reference pages it links to, embedded as resources under :/docs) in a
// window of its own, offline. F1 opens it at the part about the focused
// panel (MainWindow picks the topic).

#include <QString>
#include <QWidget>

class QTextBrowser;

namespace editor {

class UserGuide : public QWidget {
    Q_OBJECT

public:
    // The guide's sections, each a "## " heading of docs/user-guide.md.
    enum class Topic {
        GettingStarted,
        Chart,
        StepPanel,
        TransitionPanel,
        VariablesPanel,
        ProblemsPanel,
        StructuredTextPanel,
        NestedGrafcets,
        Simulation,
        Verification,
        Export,
        Keyboard,
        Packml,
    };
    static constexpr int kTopicCount = int(Topic::Packml) + 1;

    explicit UserGuide(QWidget* parent = nullptr);

    // Shows the guide at the topic's heading, and raises the window.
    void showTopic(Topic topic);
    // The heading showTopic() last put at the top (the text of a "## " line).
    QString currentHeading() const;
    QTextBrowser* browser() const { return m_browser; }

    // The heading of the topic in docs/user-guide.md (English, as the guide is).
    static QString heading(Topic topic);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void fitPictures();

    QTextBrowser* m_browser;
    QString m_currentHeading;
};

} // namespace editor
