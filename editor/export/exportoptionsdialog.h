#pragma once

#include "core/model/model.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QRadioButton;

namespace editor {

// Asks how to export the code: the dialect (IEC 61131-3 or CODESYS) and,
// for Structured Text, one file per POU in a folder or one single file. The
// single file is always IEC (core/codegen/stexport.h), so the dialect is disabled
// when it is chosen.
class ExportOptionsDialog : public QDialog {
    Q_OBJECT

public:
    enum class Kind { PlcOpen, StructuredText };

    ExportOptionsDialog(Kind kind, core::Dialect dialect, bool singleFile, QWidget* parent = nullptr);

    core::Dialect dialect() const;
    bool singleFile() const; // Structured Text only

    // "IEC 61131-3 (Beremiz, OpenPLC, TwinCAT...)", "CODESYS".
    static QString dialectText(core::Dialect dialect);

private:
    void updateDialectEnabled();

    Kind m_kind;
    QComboBox* m_dialectCombo = nullptr;
    QLabel* m_dialectHint = nullptr;
    QRadioButton* m_folderButton = nullptr;
    QRadioButton* m_singleFileButton = nullptr;
};

} // namespace editor
