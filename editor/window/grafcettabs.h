#pragma once

#include <QObject>
#include <QString>

class QTabWidget;

namespace editor {

class Document;
class GrafcetView;
class Selection;
class Settings;

// The central area's nested GRAFCET tabs, after the chart's tab (index 0):
// opening, titling, closing, and remembering them per model file. A tab is
// keyed as its GRAFCET is in the model: a GEMMA step id ("F1") or a PackML
// grafcetKey ("1/Execute"), titled "F1 Normal production" or
// "Production · Execute".
class GrafcetTabs : public QObject {
    Q_OBJECT

public:
    GrafcetTabs(QTabWidget* tabs, Document* document, Selection* selection, Settings* settings,
                QObject* parent = nullptr);

    // The tab of `key`'s GRAFCET; nullptr when it is not open.
    GrafcetView* view(const QString& key) const;
    GrafcetView* viewInFront() const;
    // Opens (or brings to the front) the tab of `key`'s GRAFCET; false when
    // the model has none there and cannot get one from its tab.
    bool open(const QString& key);
    void close(int index);
    void closeAll();
    // Tabs whose GRAFCET the model no longer has close (after a new model, an undo).
    void closeStale();
    void retitle();

    // Kept per model file (the recent files' settings) and brought back
    // when the file opens again. While switching files the tabs change
    // with the file, which is not the user's choice to remember.
    void remember();
    void restore();
    void setSwitchingFile(bool switching) { m_switchingFile = switching; }

signals:
    // A new tab's view, before it is shown: for the simulation's marks.
    void viewOpened(GrafcetView* view);
    void statusMessage(const QString& message);

private:
    bool canOpen(const QString& key) const;
    QString title(const QString& key) const;
    QString toolTip(const QString& key) const;

    QTabWidget* m_tabs;
    Document* m_document;
    Selection* m_selection;
    Settings* m_settings;
    bool m_switchingFile = false;
};

} // namespace editor
