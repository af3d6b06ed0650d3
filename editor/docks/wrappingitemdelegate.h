#pragma once

#include <QHash>
#include <QStyledItemDelegate>

class QTreeView;

namespace editor {

// The delegate of a tree view whose one column (a message) wraps over as
// many lines as its width needs, the rows sized for it and every column's
// text at the top of its row. A tree view sizes its rows without
// knowing the columns' widths, so its own word wrap only ever shows the
// first line; this delegate measures the text at the column's width and
// lays the view out again when the column is resized (the dock column beside
// the chart is narrow, and a message cut after a few words says too little).
class WrappingItemDelegate : public QStyledItemDelegate {
    Q_OBJECT

public:
    WrappingItemDelegate(QTreeView* view, int column);

    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override;

private:
    QTreeView* m_view;
    int m_column;
    // Heights by text at m_measuredWidth: the list is rebuilt at every
    // keystroke with mostly the same messages, and laying a message out
    // anew each time was most of that rebuild.
    mutable QHash<QString, int> m_heights;
    mutable int m_measuredWidth = -1;
};

} // namespace editor
