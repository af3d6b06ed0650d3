#pragma once

#include <QObject>
#include <QString>

class QMenu;
class QPoint;

namespace editor {

class Document;
class PackmlChartScene;
class PackmlChartView;
class Selection;

// Ties the PackML chart to the open Document: the scene re-reads the model
// after each change of it, and a double click on a state opens the GRAFCET
// it runs in the mode shown (its own, or the one of the mode it is the same
// as); a state without one is selected, so that its panel offers the choice.
class PackmlChartBinding : public QObject {
    Q_OBJECT

public:
    PackmlChartBinding(Document* document, PackmlChartView* view, QObject* parent = nullptr);

    // The GRAFCET key a state runs in a mode; empty when it runs none (the skeleton).
    static QString runningGrafcet(const Document& document, int mode, const QString& state);

signals:
    void openGrafcetRequested(const QString& key);

private:
    void onStateDoubleClicked(int mode, const QString& state);

    Document* m_document;
    PackmlChartView* m_view;
};

} // namespace editor
