#pragma once

#include <QLabel>

#include <array>

namespace editor {

// A word-wrapped QLabel that remembers its height for the last few widths.
//
// QLabel lays its text out anew for every heightForWidth() query, and the
// docks' layouts ask their wrapped labels dozens of times per change (the
// scroll area, the box layouts' minimum and preferred heights): most of the
// time from a keystroke to an updated dock went there. The answers are kept
// until the text, font, style or margins change.
class WrappingLabel : public QLabel {
    Q_OBJECT

public:
    explicit WrappingLabel(QWidget* parent = nullptr);
    explicit WrappingLabel(const QString& text, QWidget* parent = nullptr);

    int heightForWidth(int width) const override;

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Entry {
        int width = -1;
        int height = 0;
    };

    void forget() const;

    mutable QString m_measuredText; // the text the entries are for
    mutable std::array<Entry, 4> m_entries;
    mutable std::size_t m_next = 0; // the entry to replace next
};

} // namespace editor
