#pragma once

#include "editor/elementref.h"

#include <QList>
#include <QObject>

namespace editor {

// The element the user is working on, shared by the chart and the docks,
// and the chart elements selected with it (Ctrl+click, rubber band), which
// commands such as Hide act on together. The docks show current().
// `field` optionally names the field to focus ("condition", "tokens", "name",
// "default"...), as the Problems dock asks when it jumps to a diagnostic.
class Selection : public QObject {
    Q_OBJECT

public:
    explicit Selection(QObject* parent = nullptr);

    const ElementRef& current() const { return m_current; }
    // Every selected element, current() among them; empty when none.
    const QList<ElementRef>& elements() const { return m_elements; }
    // Selects `element` alone.
    void select(const ElementRef& element, const QString& field = {});
    // Selects all of `elements`, with `current` (one of them) shown in the docks.
    void selectMany(const QList<ElementRef>& elements, const ElementRef& current);
    void clear();

signals:
    void changed(const editor::ElementRef& element);
    // The set of elements changed (current() may be the same).
    void elementsChanged();
    // Emitted after changed() when a caller asks for a particular field.
    void focusFieldRequested(const editor::ElementRef& element, const QString& field);

private:
    ElementRef m_current;
    QList<ElementRef> m_elements;
};

} // namespace editor
