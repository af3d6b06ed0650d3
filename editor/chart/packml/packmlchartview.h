#pragma once

#include <QWidget>

class QComboBox;
class QLabel;

namespace editor {

class PackmlChartScene;
class PackmlSheetView;

// The PackML chart as the central view shows it: a unit-mode selector
// ("1 Production", "3 Manual"...) above the sheet. Picking a mode shows it
// on the chart (PackmlChartScene::setMode) and the other way round.
class PackmlChartView : public QWidget {
    Q_OBJECT

public:
    explicit PackmlChartView(PackmlChartScene* scene, QWidget* parent = nullptr);

    PackmlChartScene* chartScene() const { return m_scene; }
    PackmlSheetView* sheetView() const { return m_sheet; }
    QComboBox* modeSelector() const { return m_modes; }

signals:
    // A double click on a state: its PackTags name, in the mode shown (to
    // open its nested GRAFCET).
    void stateDoubleClicked(int mode, const QString& state);

protected:
    void changeEvent(QEvent* event) override;

private:
    void fillModes();
    void showSceneMode(int mode);
    void retranslate();

    PackmlChartScene* m_scene;
    QLabel* m_modeLabel;
    QComboBox* m_modes;
    PackmlSheetView* m_sheet;
};

} // namespace editor
