#include "editor/docks/wrappingitemdelegate.h"

#include <QApplication>
#include <QHeaderView>
#include <QStyle>
#include <QTreeView>

namespace editor {

WrappingItemDelegate::WrappingItemDelegate(QTreeView* view, int column)
    : QStyledItemDelegate(view)
    , m_view(view)
    , m_column(column)
{
    view->setItemDelegate(this);
    view->setUniformRowHeights(false);
    connect(view->header(), &QHeaderView::sectionResized, view, [view, column](int section, int, int) {
        if (section == column)
            view->doItemsLayout();
    });
}

void WrappingItemDelegate::initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const
{
    QStyledItemDelegate::initStyleOption(option, index);
    // Every column at the top of its row, beside the first line of the
    // wrapped text.
    option->displayAlignment = Qt::AlignLeft | Qt::AlignTop;
    option->decorationAlignment = Qt::AlignLeft | Qt::AlignTop;
    if (index.column() != m_column)
        return;
    option->features |= QStyleOptionViewItem::WrapText;
    option->textElideMode = Qt::ElideNone;
}

QSize WrappingItemDelegate::sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const
{
    const int width = m_view->header()->sectionSize(m_column);
    if (index.column() != m_column || width <= 0)
        return QStyledItemDelegate::sizeHint(option, index);
    constexpr qsizetype kRememberedTexts = 1000; // a long session types many messages
    if (width != m_measuredWidth || m_heights.size() >= kRememberedTexts) {
        m_heights.clear();
        m_measuredWidth = width;
    }
    const QString text = index.data(Qt::DisplayRole).toString();
    const auto known = m_heights.constFind(text);
    if (known != m_heights.constEnd())
        return {width, *known};
    QStyleOptionViewItem wrapped = option;
    initStyleOption(&wrapped, index);
    // The style lays the text out at the width of the rectangle it is given
    // (the column's), when the rectangle is valid: its height is not used.
    wrapped.rect = QRect(0, 0, width, 1);
    const QStyle* style = wrapped.widget ? wrapped.widget->style() : QApplication::style();
    const QSize size = style->sizeFromContents(QStyle::CT_ItemViewItem, &wrapped, QSize(), wrapped.widget);
    constexpr int kRowGap = 3; // wrapped rows apart, so that each message reads as one
    const int height = size.height() + kRowGap;
    m_heights.insert(text, height);
    return {width, height};
}

} // namespace editor
