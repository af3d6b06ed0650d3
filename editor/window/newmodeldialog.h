#pragma once

#include "core/model/model.h"

#include <QDialog>

class QButtonGroup;

namespace editor {

class Settings;

// File > New: which fixed chart the new model fills in. GEMMA, or PackML
// in either edition of ISA-TR88.00.02 (their options differ, spec
// packml.md §5.1); the choice is offered again next time.
class NewModelDialog : public QDialog {
    Q_OBJECT

public:
    enum class Choice { Gemma, Packml2015, Packml2022 };

    explicit NewModelDialog(Choice initial, QWidget* parent = nullptr);

    Choice choice() const;
    void setChoice(Choice choice);

    // The name a choice is kept under in the settings, and back.
    static QString settingName(Choice choice);
    static Choice fromSettingName(const QString& name);
    // The new model of a choice, with the user's default cycle time and dialect.
    static core::Model newModel(Choice choice, const Settings& settings);

private:
    QButtonGroup* m_choices;
};

} // namespace editor
