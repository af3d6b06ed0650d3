#pragma once

// The Machine tab of the central area, after the chart's tab: there while
// the model has a virtual machine (a file that describes one, or the
// Machine dock's first component), gone when it has none. It has no close
// button: it comes and goes with the machine.

#include <QObject>
#include <QPointer>

class QTabWidget;

namespace editor {

class Document;
class MachineView;
class SimulationSession;

class MachineTab : public QObject {
    Q_OBJECT

public:
    MachineTab(QTabWidget* tabs, Document* document, SimulationSession* session, QObject* parent = nullptr);
    ~MachineTab() override;

    // nullptr while the model has no machine.
    MachineView* view() const;
    static QString title();

private:
    void sync();
    void retitle();

    QTabWidget* m_tabs;
    Document* m_document;
    SimulationSession* m_session;
    QPointer<MachineView> m_view;
};

} // namespace editor
