#pragma once

#include "core/checks/diagnostic.h"

#include <QWidget>

#include <vector>

class QVBoxLayout;

namespace editor {

class Document;

// The problems of one element, one row each (severity icon and message), as
// the Step and Transition docks show them under their fields. Hidden when
// there are none.
class DiagnosticList : public QWidget {
    Q_OBJECT

public:
    explicit DiagnosticList(QWidget* parent = nullptr);

    // Given the document, a problem with a quick fix (an undeclared name:
    // editor/docks/declarationfix.h) gets a button under its message that applies it.
    void setDocument(Document* document) { m_document = document; }
    void setDiagnostics(const std::vector<core::Diagnostic>& diagnostics);
    int count() const { return static_cast<int>(m_diagnostics.size()); }

protected:
    void changeEvent(QEvent* event) override;

private:
    void rebuildRows();
    void addFixButton(const core::Diagnostic& diagnostic);

    QVBoxLayout* m_layout;
    Document* m_document = nullptr;
    std::vector<core::Diagnostic> m_diagnostics;
};

} // namespace editor
