#pragma once

#include <QObject>

class QAbstractItemView;

namespace editor {

// Opens the editor of the cell a double-click lands on, even when the
// click before it went elsewhere. QAbstractItemView opens it only when
// both clicks pressed that cell, but the first click after typing in a
// cell with a completion list open only closes the list: without this, the
// next cell needs a second double-click.
class DoubleClickEdit : public QObject {
    Q_OBJECT

public:
    // Installs a filter owned by the view.
    static void install(QAbstractItemView* view);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit DoubleClickEdit(QAbstractItemView* view);

    QAbstractItemView* m_view;
};

} // namespace editor
