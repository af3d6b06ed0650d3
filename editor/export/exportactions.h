#pragma once

#include "editor/export/chartexport.h"

#include "core/checks/diagnostic.h"
#include "core/model/model.h"

#include <QObject>

#include <functional>
#include <QString>
#include <QStringList>

#include <vector>

class QAction;
class QWidget;

namespace editor {

class ChartScene;
class GrafcetScene;
class PackmlChartScene;
class Document;
class Settings;

// The exports of the File menu: PLCopen XML, Structured Text, GG-Generator
// JSON, pictures of the chart, the specification PDF and printing. Each
// action asks what it needs (options, file name), asks before exporting code
// from a model with errors, writes the file and reports. The write*
// functions do the writing alone, for the window's own callers and the tests.
class ExportActions : public QObject {
    Q_OBJECT

public:
    ExportActions(Document& document, ChartScene& scene, Settings& settings, QWidget* window);

    QAction* plcOpenAction() const { return m_plcOpen; }
    QAction* structuredTextAction() const { return m_structuredText; }
    QAction* ggGeneratorAction() const { return m_ggGenerator; }
    QAction* chartAction() const { return m_chart; }
    QAction* specificationAction() const { return m_specification; }
    QAction* printAction() const { return m_print; }

    // False with a message for the user when the file cannot be written.
    bool writePlcOpen(const QString& path, core::Dialect dialect, QString* errorMessage) const;
    bool writeStFolder(const QString& folder, core::Dialect dialect, QString* errorMessage) const;
    bool writeStSingleFile(const QString& path, QString* errorMessage) const;
    bool writeGGGenerator(const QString& path, QString* errorMessage) const;
    // The whole model as one PDF (editor/export/specificationexport.h).
    bool writeSpecification(const QString& path, QString* errorMessage) const;
    // Export Specification's work after its file dialog: the PDF written
    // with a progress dialog whose Cancel leaves the file as it was, then
    // the report. False when it failed or was cancelled.
    bool exportSpecificationTo(const QString& path);

    void retranslate();

    // Export Chart and Print take the nested GRAFCET in front when there is
    // one (the window says which), the GEMMA chart otherwise.
    void setGrafcetInFront(std::function<GrafcetScene*()> grafcetInFront) { m_grafcetInFront = std::move(grafcetInFront); }
    // The PackML chart, which Export Chart and Print take for a PackML model.
    void setPackmlChart(PackmlChartScene* scene) { m_packmlChart = scene; }
    // Writes the picture in front; Export Chart's work after its dialog.
    bool writeChart(const QString& path, ChartExport::Format format, QString* errorMessage) const;

    // The question asked before exporting code from a model with errors:
    // their count and the first few. True when there are none or the user
    // goes on.
    static bool confirmErrors(QWidget* parent, const std::vector<core::Diagnostic>& diagnostics);
    // The name an export file starts with: the model file's ("press" for
    // press.json), else the model's name (its PLC program's), else "untitled".
    static QString suggestedBaseName(const QString& modelPath, const core::Model& model);
    // The file Export Specification suggests: "<model name> specification.pdf"
    // (the model's name, else the file's, as a file system takes it).
    static QString suggestedSpecificationName(const QString& modelPath, const core::Model& model);
    // The question asked before a GG-Generator export that leaves part of
    // the model out (nested GRAFCETs, variable kinds, the evolution rule).
    // True when nothing is lost or the user goes on.
    static bool confirmGGGeneratorLosses(QWidget* parent, const core::Model& model);
    // What the GG-Generator file would leave out, one translated sentence each.
    static QStringList ggGeneratorLossTexts(const core::Model& model);

signals:
    // A short report for the status bar ("Exported to ...").
    void exported(const QString& message);

private:
    void exportPlcOpen();
    void exportStructuredText();
    void exportGGGenerator();
    void exportChart();
    void exportSpecification();
    void print();

    // A warning with the lines as its details, Cancel by default; true for Export Anyway.
    static bool askExportAnyway(QWidget* parent, const QString& title, const QString& text, const QStringList& lines);
    // The dialect of the last export, or the model's before the first.
    core::Dialect lastDialect() const;
    // The file dialog for a new file, starting in the last export folder
    // with a name made from the model name (or `name` when given); empty
    // when cancelled.
    QString askSavePath(const QString& title, const QString& suffix, const QString& filters,
                        QString* selectedFilter = nullptr, const QString& name = QString());
    void reportResult(bool ok, const QString& path, const QString& errorMessage);

    Document& m_document;
    ChartScene& m_scene;
    std::function<GrafcetScene*()> m_grafcetInFront;
    PackmlChartScene* m_packmlChart = nullptr;
    Settings& m_settings;
    QWidget* m_window;
    QAction* m_plcOpen;
    QAction* m_structuredText;
    QAction* m_ggGenerator;
    QAction* m_chart;
    QAction* m_specification;
    QAction* m_print;
};

} // namespace editor
