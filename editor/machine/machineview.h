#pragma once

// The Machine tab's view of its MachineScene: the whole schematic at its
// natural size when it fits, scaled down to fit (never below kMinScale, so
// the labels stay readable: it scrolls then) when the window is narrow.

#include <QGraphicsView>

namespace editor {

class Document;
class MachineScene;
class SimulationSession;

class MachineView : public QGraphicsView {
    Q_OBJECT

public:
    static constexpr double kMinScale = 0.75;

    MachineView(Document* document, SimulationSession* session, QWidget* parent = nullptr);

    MachineScene* machineScene() const { return m_scene; }

signals:
    void languageChanged();

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void fit();

    MachineScene* m_scene;
};

} // namespace editor
