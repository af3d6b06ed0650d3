#include "editor/docks/conditionedit.h"

#include "editor/docks/undoshortcutfilter.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QFontDatabase>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QScrollBar>
#include <QStringListModel>
#include <QTextBlock>
#include <QToolTip>

#include <algorithm>
#include <cctype>

namespace editor {

namespace {

bool isIdentifierCharacter(QChar c)
{
    const char16_t u = c.unicode();
    return u < 128 && (std::isalnum(static_cast<unsigned char>(u)) || u == u'_');
}

// Conditions are one paragraph: pasted line breaks and tabs become spaces.
QString singleParagraph(QString text)
{
    text.replace(QLatin1String("\r\n"), QLatin1String(" "));
    for (QChar& c : text) {
        if (c == u'\n' || c == u'\r' || c == u'\t' || c == QChar::ParagraphSeparator || c == QChar::LineSeparator)
            c = u' ';
    }
    return text;
}

} // namespace

ConditionEdit::ConditionEdit(QWidget* parent)
    : QPlainTextEdit(parent)
    , m_completer(new QCompleter(this))
    , m_names(new QStringListModel(this))
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setTabChangesFocus(true);
    setUndoRedoEnabled(false); // the document's undo stack is the history
    UndoShortcutFilter::install(this);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);

    m_completer->setModel(m_names);
    m_completer->setModelSorting(QCompleter::CaseInsensitivelySortedModel);
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setCompletionMode(QCompleter::PopupCompletion);
    m_completer->setWrapAround(false);
    m_completer->setWidget(this);
    connect(m_completer, qOverload<const QString&>(&QCompleter::activated), this, &ConditionEdit::insertCompletion);
    connect(this, &QPlainTextEdit::textChanged, this, &ConditionEdit::onTextChanged);
}

void ConditionEdit::setText(const QString& text)
{
    if (text == toPlainText())
        return;
    const int position = textCursor().position();
    m_settingText = true;
    setPlainText(text);
    m_settingText = false;
    QTextCursor cursor = textCursor();
    cursor.setPosition(std::min(position, static_cast<int>(text.size())));
    setTextCursor(cursor);
    updateExtraSelections();
}

void ConditionEdit::setProblems(const QList<Problem>& problems)
{
    m_problems = problems;
    updateExtraSelections();
}

void ConditionEdit::setVariableNames(const QStringList& names)
{
    QStringList sorted = names;
    sorted.sort(Qt::CaseInsensitive); // what CaseInsensitivelySortedModel promises
    if (sorted != m_names->stringList())
        m_names->setStringList(sorted);
}

void ConditionEdit::selectRange(int begin, int end)
{
    const int length = static_cast<int>(toPlainText().size());
    QTextCursor cursor = textCursor();
    cursor.setPosition(std::clamp(begin, 0, length));
    cursor.setPosition(std::clamp(end, 0, length), QTextCursor::KeepAnchor);
    setTextCursor(cursor);
    setFocus(Qt::OtherFocusReason);
}

int ConditionEdit::positionOfByte(const QString& text, std::size_t byteOffset)
{
    std::size_t bytes = 0;
    int position = 0;
    const int length = static_cast<int>(text.size());
    while (position < length && bytes < byteOffset) {
        const char32_t code = text.at(position).isHighSurrogate() && position + 1 < length
            ? QChar::surrogateToUcs4(text.at(position), text.at(position + 1))
            : text.at(position).unicode();
        bytes += code < 0x80 ? 1 : code < 0x800 ? 2 : code < 0x10000 ? 3 : 4;
        position += code >= 0x10000 ? 2 : 1;
    }
    return position;
}

int ConditionEdit::linesHeight(int lines) const
{
    const int margins = static_cast<int>(2 * document()->documentMargin()) + 2 * frameWidth();
    return fontMetrics().lineSpacing() * lines + margins;
}

QSize ConditionEdit::sizeHint() const
{
    return { QPlainTextEdit::sizeHint().width(), linesHeight(3) };
}

QSize ConditionEdit::minimumSizeHint() const
{
    return { QPlainTextEdit::minimumSizeHint().width(), linesHeight(2) };
}

void ConditionEdit::onTextChanged()
{
    if (!m_settingText)
        emit textEdited(toPlainText());
}

std::pair<int, int> ConditionEdit::displayedRange(const Problem& problem) const
{
    const int length = static_cast<int>(toPlainText().size());
    int begin = std::clamp(problem.begin, 0, length);
    int end = std::clamp(problem.end, begin, length);
    if (begin == end) {
        if (end < length)
            ++end;
        else if (begin > 0)
            --begin;
    }
    return { begin, end };
}

void ConditionEdit::updateExtraSelections()
{
    QList<QTextEdit::ExtraSelection> selections;
    for (const Problem& problem : m_problems) {
        const auto [begin, end] = displayedRange(problem);
        if (begin == end)
            continue;
        QTextEdit::ExtraSelection selection;
        selection.cursor = QTextCursor(document());
        selection.cursor.setPosition(begin);
        selection.cursor.setPosition(end, QTextCursor::KeepAnchor);
        selection.format.setUnderlineStyle(QTextCharFormat::SpellCheckUnderline);
        selection.format.setUnderlineColor(problem.error ? QColor(Qt::red) : QColor(0xe0, 0x90, 0x00));
        selections << selection;
    }
    setExtraSelections(selections);
}

const ConditionEdit::Problem* ConditionEdit::problemAt(const QPoint& viewportPosition) const
{
    for (const Problem& problem : m_problems) {
        const auto [begin, end] = displayedRange(problem);
        QTextCursor cursor(document());
        for (int position = begin; position < end; ++position) {
            cursor.setPosition(position);
            const QRect left = cursorRect(cursor);
            cursor.setPosition(position + 1);
            const QRect right = cursorRect(cursor);
            if (left.top() != right.top())
                continue; // the character ends a wrapped line
            const QRect character(left.left(), left.top(), std::max(right.left() - left.left(), 2), left.height());
            if (character.contains(viewportPosition))
                return &problem;
        }
    }
    return nullptr;
}

bool ConditionEdit::viewportEvent(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        if (const Problem* problem = problemAt(help->pos()))
            QToolTip::showText(help->globalPos(), problem->message, viewport());
        else if (!toolTip().isEmpty())
            QToolTip::showText(help->globalPos(), toolTip(), viewport());
        else
            QToolTip::hideText();
        return true;
    }
    return QPlainTextEdit::viewportEvent(event);
}

void ConditionEdit::focusInEvent(QFocusEvent* event)
{
    m_completer->setWidget(this);
    QPlainTextEdit::focusInEvent(event);
}

QString ConditionEdit::identifierBeforeCursor() const
{
    const QTextCursor cursor = textCursor();
    const QString text = cursor.block().text();
    const int end = cursor.positionInBlock();
    int begin = end;
    while (begin > 0 && isIdentifierCharacter(text.at(begin - 1)))
        --begin;
    return text.mid(begin, end - begin);
}

void ConditionEdit::keyPressEvent(QKeyEvent* event)
{
    QAbstractItemView* popup = m_completer->popup();
    const int key = event->key();
    if (popup->isVisible()) {
        switch (key) {
        case Qt::Key_Enter:
        case Qt::Key_Return:
        case Qt::Key_Escape:
        case Qt::Key_Tab:
        case Qt::Key_Backtab:
            event->ignore(); // the completer takes them
            return;
        default:
            break;
        }
    }
    const bool forced = key == Qt::Key_Space && (event->modifiers() & Qt::ControlModifier);
    if (!forced) {
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            event->accept(); // one paragraph
            return;
        }
        QPlainTextEdit::keyPressEvent(event);
    }
    const QString typed = event->text();
    const bool editsIdentifier = key == Qt::Key_Backspace || key == Qt::Key_Delete
        || (!typed.isEmpty() && isIdentifierCharacter(typed.back()));
    const QString prefix = identifierBeforeCursor();
    const bool startsWithDigit = !prefix.isEmpty() && prefix.front().isDigit();
    if (!forced && (!editsIdentifier || prefix.isEmpty() || startsWithDigit)) {
        popup->hide();
        return;
    }
    updateCompletions(startsWithDigit ? QString() : prefix, forced);
}

void ConditionEdit::updateCompletions(const QString& prefix, bool forced)
{
    QAbstractItemView* popup = m_completer->popup();
    if (prefix != m_completer->completionPrefix())
        m_completer->setCompletionPrefix(prefix);
    const int count = m_completer->completionCount();
    // Nothing to offer, or exactly what is already written.
    const bool nothingNew = count == 0 || (!forced && count == 1 && m_completer->currentCompletion() == prefix);
    if (nothingNew) {
        popup->hide();
        return;
    }
    popup->setCurrentIndex(m_completer->completionModel()->index(0, 0));
    QRect rectangle = cursorRect();
    rectangle.setWidth(popup->sizeHintForColumn(0) + popup->verticalScrollBar()->sizeHint().width());
    m_completer->complete(rectangle);
}

void ConditionEdit::insertCompletion(const QString& completion)
{
    if (m_completer->widget() != this)
        return;
    // The whole identifier under the cursor becomes the declared spelling.
    QTextCursor cursor = textCursor();
    const QString text = cursor.block().text();
    int begin = cursor.positionInBlock();
    int end = begin;
    while (begin > 0 && isIdentifierCharacter(text.at(begin - 1)))
        --begin;
    while (end < text.size() && isIdentifierCharacter(text.at(end)))
        ++end;
    const int blockStart = cursor.block().position();
    cursor.setPosition(blockStart + begin);
    cursor.setPosition(blockStart + end, QTextCursor::KeepAnchor);
    cursor.insertText(completion);
    setTextCursor(cursor);
}

bool ConditionEdit::canInsertFromMimeData(const QMimeData* source) const
{
    return source->hasText();
}

void ConditionEdit::insertFromMimeData(const QMimeData* source)
{
    if (!source->hasText())
        return;
    QTextCursor cursor = textCursor();
    cursor.insertText(singleParagraph(source->text()));
    setTextCursor(cursor);
    ensureCursorVisible();
}

} // namespace editor
