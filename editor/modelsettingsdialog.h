#pragma once

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace editor {

class Document;
class Settings;

// Edit > Model Settings: the model name, the PLC cycle time and the dialect
// of the generated code. Accepting pushes one undoable edit for what
// changed; it can also make the cycle time and dialect the defaults of new
// models.
class ModelSettingsDialog : public QDialog {
    Q_OBJECT

public:
    ModelSettingsDialog(Document& document, Settings& settings, QWidget* parent = nullptr);

    void accept() override;

private:
    void apply();

    Document& m_document;
    Settings& m_settings;
    QLineEdit* m_nameEdit;
    QSpinBox* m_cycleTimeSpin;
    QComboBox* m_dialectCombo;
    QCheckBox* m_defaultsCheck;
};

} // namespace editor
