#pragma once

#include <QList>
#include <QPlainTextEdit>
#include <QStringList>

#include <cstddef>

class QCompleter;
class QStringListModel;

namespace editor {

// The editor of a transition condition: one paragraph of Structured Text
// (line breaks become spaces), problems underlined with a red wave at their
// span with the message as tooltip, and completion of the variable name
// under the cursor (typing, or Ctrl+Space).
class ConditionEdit : public QPlainTextEdit {
    Q_OBJECT

public:
    // A range [begin, end) of text() that the checks object to. An empty
    // range (missing input at the end) is underlined on the character next to it.
    struct Problem {
        int begin = 0;
        int end = 0;
        QString message;
        bool error = true; // else a warning
    };

    explicit ConditionEdit(QWidget* parent = nullptr);

    QString text() const { return toPlainText(); }
    // Replaces the text when it differs, keeping the cursor position where
    // possible; emits no textEdited().
    void setText(const QString& text);

    void setProblems(const QList<Problem>& problems);
    const QList<Problem>& problems() const { return m_problems; }

    // The declared variables the completer offers.
    void setVariableNames(const QStringList& names);
    QCompleter* completer() const { return m_completer; }

    // Selects [begin, end) of text() and takes the focus.
    void selectRange(int begin, int end);

    // The position in `text` of a UTF-8 byte offset: core spans count bytes.
    static int positionOfByte(const QString& text, std::size_t byteOffset);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    // The user changed the text (not setText()).
    void textEdited(const QString& text);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    bool viewportEvent(QEvent* event) override;
    bool canInsertFromMimeData(const QMimeData* source) const override;
    void insertFromMimeData(const QMimeData* source) override;

private:
    void onTextChanged();
    void updateExtraSelections();
    void updateCompletions(const QString& prefix, bool forced);
    void insertCompletion(const QString& completion);
    QString identifierBeforeCursor() const;
    const Problem* problemAt(const QPoint& viewportPosition) const;
    // The range a problem is underlined on.
    std::pair<int, int> displayedRange(const Problem& problem) const;
    int linesHeight(int lines) const;

    QCompleter* m_completer;
    QStringListModel* m_names;
    QList<Problem> m_problems;
    bool m_settingText = false;
};

} // namespace editor
