#pragma once

#include "editor/elementref.h"

#include <QObject>

namespace editor {

// The element the user is working on, shared by the chart and the docks.
// `field` optionally names the field to focus ("condition", "tokens", "name",
// "default"...), as the Problems dock asks when it jumps to a diagnostic.
class Selection : public QObject {
    Q_OBJECT

public:
    explicit Selection(QObject* parent = nullptr);

    const ElementRef& current() const { return m_current; }
    void select(const ElementRef& element, const QString& field = {});
    void clear();

signals:
    void changed(const editor::ElementRef& element);
    // Emitted after changed() when a caller asks for a particular field.
    void focusFieldRequested(const editor::ElementRef& element, const QString& field);

private:
    ElementRef m_current;
};

} // namespace editor
