#pragma once

#include <QHash>
#include <QString>
#include <QWidget>

class QGridLayout;
class QLabel;
class QLineEdit;
class QToolButton;

namespace editor {

class LampIndicator;
class PackmlSimulationSession;

// The variables of a PackML simulation in the PackML Simulation dock: the
// inputs the user plays (BOOLs as toggles, the others, PackTags included,
// as text fields set on Enter) and what the program writes (BOOLs as lamps,
// the others as values, StateCurrent and UnitModeCurrent included), for the
// scan the session shows.
class PackmlVariablesPanel : public QWidget {
    Q_OBJECT

public:
    explicit PackmlVariablesPanel(PackmlSimulationSession* session, QWidget* parent = nullptr);

    // The program's variables, once the session is active; none while not.
    void rebuild();
    void refresh();
    void retranslate();

    QToolButton* inputToggle(const QString& variable) const { return m_inputToggles.value(variable, nullptr); }
    QLineEdit* inputField(const QString& variable) const { return m_inputFields.value(variable, nullptr); }
    LampIndicator* outputLamp(const QString& variable) const { return m_outputLamps.value(variable, nullptr); }
    QLabel* outputValue(const QString& variable) const { return m_outputValues.value(variable, nullptr); }

private:
    void clear();
    void addInput(const QString& name, bool isBool);
    void addOutput(const QString& name, bool isBool);

    PackmlSimulationSession* m_session;
    QLabel* m_inputsTitle;
    QGridLayout* m_inputsGrid;
    QLabel* m_outputsTitle;
    QGridLayout* m_outputsGrid;
    QHash<QString, QToolButton*> m_inputToggles;
    QHash<QString, QLineEdit*> m_inputFields;
    QHash<QString, LampIndicator*> m_outputLamps;
    QHash<QString, QLabel*> m_outputValues;
};

} // namespace editor
