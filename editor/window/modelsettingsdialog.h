#pragma once

#include "core/model/model.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace editor {

class Document;
class PackmlSettingsWidget;
class Settings;

// Edit > Model Settings: the model name, the PLC cycle time, the dialect
// of the generated code and the evolution rule of the nested GRAFCETs
// (spec grafcet-layer.md §4.1), with a sentence saying what the chosen rule
// means; for a PackML model also its edition, options and initial state
// (PackmlSettingsWidget). Accepting pushes one undoable edit for what
// changed; it can also make the cycle time and dialect the defaults of new
// models.
class ModelSettingsDialog : public QDialog {
    Q_OBJECT

public:
    ModelSettingsDialog(Document& document, Settings& settings, QWidget* parent = nullptr);

    void accept() override;

    // What the rule means, one sentence.
    static QString evolutionRuleDescription(core::EvolutionRule rule);

private:
    void apply();
    void updateEvolutionDescription();

    Document& m_document;
    Settings& m_settings;
    QLineEdit* m_nameEdit;
    QSpinBox* m_cycleTimeSpin;
    QComboBox* m_dialectCombo;
    QComboBox* m_evolutionCombo;
    QLabel* m_evolutionDescription;
    QCheckBox* m_defaultsCheck;
    PackmlSettingsWidget* m_packmlSettings = nullptr; // PackML models only
};

} // namespace editor
