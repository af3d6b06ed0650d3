#pragma once

#include "core/model/grafcet.h"

#include <QDialog>

#include <vector>

class QDialogButtonBox;
class QLabel;
class QListWidget;

namespace editor {

// Connect Directly: the upstream and downstream steps of one transition as
// two lists of checkable steps, for the shapes the structured operations do
// not reach. Each list shows the transition's current steps first, in
// their branch order, then the others; OK needs a step ticked in each (the
// model's invariant: a transition leaves a step and activates one), and a
// line above the buttons says which list lacks one while OK is disabled.
class ConnectTransitionDialog : public QDialog {
    Q_OBJECT

public:
    ConnectTransitionDialog(const core::Grafcet& grafcet, int transition, const QString& grafcetName,
                            QWidget* parent = nullptr);

    // The ticked steps, in list order.
    std::vector<int> upstream() const;
    std::vector<int> downstream() const;
    QListWidget* upstreamList() const { return m_upstream; }
    QListWidget* downstreamList() const { return m_downstream; }
    // Why OK is disabled; hidden while it is enabled.
    QLabel* reasonLabel() const { return m_reason; }

private:
    QListWidget* createList(const core::Grafcet& grafcet, const std::vector<int>& current, const QString& name);
    void updateOk();

    QListWidget* m_upstream = nullptr;
    QListWidget* m_downstream = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QLabel* m_reason = nullptr;
};

} // namespace editor
