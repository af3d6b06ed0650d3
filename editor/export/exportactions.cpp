#include "editor/export/exportactions.h"

#include "editor/app/settings.h"
#include "editor/chart/gemma/chartscene.h"
#include "editor/document.h"
#include "editor/export/chartexport.h"
#include "editor/export/packmlchartexport.h"
#include "editor/export/exportoptionsdialog.h"
#include "editor/export/specificationexport.h"
#include "editor/grafcet/grafcetexport.h"
#include "editor/grafcet/grafcetscene.h"
#include "editor/text/diagnostictext.h"

#include "core/formats/fileio.h"
#include "core/formats/gggeneratorformat.h"
#include "core/formats/modelfiles.h"
#include "core/codegen/plcopenwriter.h"
#include "core/codegen/stexport.h"
#include "core/codegen/stgenerator.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPrintDialog>
#include <QPrinter>
#include <QProgressDialog>
#include <QPushButton>
#include <QRegularExpression>

#include <algorithm>

namespace editor {

namespace {

// How many errors the confirmation lists before "and N more".
constexpr int kListedErrors = 5;

// A specification written faster than this shows no progress dialog.
constexpr int kProgressDelayMs = 300;

std::string localPath(const QString& path)
{
    return QFile::encodeName(path).toStdString();
}

bool report(const core::Status& status, QString* errorMessage)
{
    if (!status && errorMessage)
        *errorMessage = QString::fromStdString(status.message);
    return status.ok;
}

} // namespace

QString ExportActions::suggestedBaseName(const QString& modelPath, const core::Model& model)
{
    // "press.json" and "press.ggstudio.json" both give "press"; characters
    // file systems refuse become '_'.
    QString name = QFileInfo(modelPath).fileName().section('.', 0, 0);
    if (name.isEmpty())
        name = QString::fromStdString(model.settings().name).trimmed();
    name.replace(QRegularExpression(QStringLiteral(R"([\\/:*?"<>|\x00-\x1f])")), QStringLiteral("_"));
    return name.isEmpty() ? tr("untitled") : name;
}

QString ExportActions::suggestedSpecificationName(const QString& modelPath, const core::Model& model)
{
    QString name = QString::fromStdString(model.settings().name).simplified();
    name.replace(QRegularExpression(QStringLiteral(R"([\\/:*?"<>|\x00-\x1f])")), QStringLiteral("_"));
    if (name.isEmpty())
        name = suggestedBaseName(modelPath, model);
    return SpecificationExport::suggestedFileName(name);
}

namespace {

QString withSuffix(QString path, const QString& suffix)
{
    if (QFileInfo(path).suffix().isEmpty())
        path += '.' + suffix;
    return path;
}

} // namespace

ExportActions::ExportActions(Document& document, ChartScene& scene, Settings& settings, QWidget* window)
    : QObject(window)
    , m_document(document)
    , m_scene(scene)
    , m_settings(settings)
    , m_window(window)
    , m_plcOpen(new QAction(this))
    , m_structuredText(new QAction(this))
    , m_ggGenerator(new QAction(this))
    , m_chart(new QAction(this))
    , m_specification(new QAction(this))
    , m_print(new QAction(this))
{
    m_plcOpen->setObjectName("exportPlcOpenAction");
    m_structuredText->setObjectName("exportStructuredTextAction");
    m_ggGenerator->setObjectName("exportGGGeneratorAction");
    m_chart->setObjectName("exportChartAction");
    m_specification->setObjectName("exportSpecificationAction");
    m_print->setObjectName("printAction");
    m_plcOpen->setShortcut(Qt::CTRL | Qt::Key_E);
    m_print->setShortcut(QKeySequence::Print);
    connect(m_plcOpen, &QAction::triggered, this, &ExportActions::exportPlcOpen);
    connect(m_structuredText, &QAction::triggered, this, &ExportActions::exportStructuredText);
    connect(m_ggGenerator, &QAction::triggered, this, &ExportActions::exportGGGenerator);
    connect(m_chart, &QAction::triggered, this, &ExportActions::exportChart);
    connect(m_specification, &QAction::triggered, this, &ExportActions::exportSpecification);
    connect(m_print, &QAction::triggered, this, &ExportActions::print);
    retranslate();
}

void ExportActions::retranslate()
{
    m_plcOpen->setText(tr("Export &PLCopen XML…"));
    m_plcOpen->setStatusTip(tr("Write the PLC program as PLCopen XML, to import into a PLC programming tool"));
    m_structuredText->setText(tr("Export &Structured Text…"));
    m_structuredText->setStatusTip(tr("Write the PLC program as IEC 61131-3 Structured Text files"));
    m_ggGenerator->setText(tr("Export &GG-Generator JSON…"));
    m_ggGenerator->setStatusTip(tr("Save the model in the format of the GG-Generator web tool"));
    m_chart->setText(tr("Export &Chart…"));
    m_chart->setStatusTip(tr("Save the chart as an SVG, PNG or PDF picture"));
    m_specification->setText(tr("Export Speci&fication…"));
    m_specification->setStatusTip(tr("Write the whole model as one PDF document: the chart, the states, the "
                                     "variables, every nested GRAFCET and the outline of the generated code"));
    m_print->setText(tr("&Print…"));
    m_print->setStatusTip(tr("Print the chart"));
}

bool ExportActions::writePlcOpen(const QString& path, core::Dialect dialect, QString* errorMessage) const
{
    const core::Model& model = m_document.model();
    const std::string xml = core::writePlcOpenXml(core::buildPlcProject(model, dialect), model);
    return report(core::writeFileAtomically(localPath(path), xml), errorMessage);
}

bool ExportActions::writeStFolder(const QString& folder, core::Dialect dialect, QString* errorMessage) const
{
    return report(core::exportStFolder(core::buildPlcProject(m_document.model(), dialect), localPath(folder)),
                  errorMessage);
}

bool ExportActions::writeStSingleFile(const QString& path, QString* errorMessage) const
{
    return report(core::exportStSingleFile(m_document.model(), localPath(path)), errorMessage);
}

bool ExportActions::writeGGGenerator(const QString& path, QString* errorMessage) const
{
    return report(core::saveModelFile(m_document.model(), localPath(path), core::ModelFormat::GGGenerator),
                  errorMessage);
}

bool ExportActions::confirmErrors(QWidget* parent, const std::vector<core::Diagnostic>& diagnostics)
{
    std::vector<const core::Diagnostic*> errors;
    for (const core::Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.severity == core::Severity::Error)
            errors.push_back(&diagnostic);
    }
    if (errors.empty())
        return true;

    QStringList lines;
    const int listed = std::min<int>(kListedErrors, int(errors.size()));
    for (int i = 0; i < listed; ++i) {
        lines << QStringLiteral("• ") + diagnosticText(*errors[i]); // the messages name their element
    }
    if (int(errors.size()) > listed)
        lines << tr("… and %n more", nullptr, int(errors.size()) - listed);

    return askExportAnyway(parent, tr("Export a Model with Errors"),
                           tr("The model has %n error(s). The generated code marks each one with a comment, "
                              "but it may not compile or may not behave as intended.",
                              nullptr, int(errors.size())),
                           lines);
}

bool ExportActions::askExportAnyway(QWidget* parent, const QString& title, const QString& text,
                                    const QStringList& lines)
{
    QMessageBox box(QMessageBox::Warning, title, text, QMessageBox::Cancel, parent);
    box.setInformativeText(lines.join('\n'));
    QPushButton* exportButton = box.addButton(tr("&Export Anyway"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == exportButton;
}

QStringList ExportActions::ggGeneratorLossTexts(const core::Model& model)
{
    QStringList texts;
    for (const core::GGGeneratorLoss& loss : core::ggGeneratorLosses(model)) {
        switch (loss.kind) {
        case core::GGGeneratorLoss::Kind::NestedGrafcets: {
            QStringList steps;
            for (const std::string& step : loss.steps)
                steps << QString::fromStdString(step);
            texts << tr("The nested GRAFCETs of %1: GG-Generator has no place for nested behaviour.")
                         .arg(steps.join(QStringLiteral(", ")));
            break;
        }
        case core::GGGeneratorLoss::Kind::VariableKinds:
            texts << tr("The variable kinds (output, internal): GG-Generator reads every variable as an input.");
            break;
        case core::GGGeneratorLoss::Kind::UntilStableRule:
            texts << tr("The until-stable evolution rule: GG-Generator knows one evolution per scan only.");
            break;
        case core::GGGeneratorLoss::Kind::Properties:
            texts << tr("The verification properties: GG-Generator has no place for them.");
            break;
        }
    }
    return texts;
}

bool ExportActions::confirmGGGeneratorLosses(QWidget* parent, const core::Model& model)
{
    const QStringList losses = ggGeneratorLossTexts(model);
    if (losses.isEmpty())
        return true;
    QStringList lines;
    for (const QString& loss : losses)
        lines << QStringLiteral("• ") + loss;
    return askExportAnyway(parent, tr("Export to GG-Generator"),
                           tr("The GG-Generator file will leave out part of this model. Your model and its own "
                              "file keep everything."),
                           lines);
}

void ExportActions::exportPlcOpen()
{
    if (!confirmErrors(m_window, m_document.diagnostics()))
        return;
    ExportOptionsDialog options(ExportOptionsDialog::Kind::PlcOpen, lastDialect(), false, m_window);
    if (options.exec() != QDialog::Accepted)
        return;
    m_settings.setLastExportDialect(options.dialect());
    const QString path = askSavePath(tr("Export PLCopen XML"), QStringLiteral("xml"), tr("PLCopen XML (*.xml)"));
    if (path.isEmpty())
        return;
    QString error;
    const bool ok = writePlcOpen(path, options.dialect(), &error);
    reportResult(ok, path, error);
}

void ExportActions::exportStructuredText()
{
    if (!confirmErrors(m_window, m_document.diagnostics()))
        return;
    ExportOptionsDialog options(ExportOptionsDialog::Kind::StructuredText, lastDialect(),
                                m_settings.lastStExportSingleFile(), m_window);
    if (options.exec() != QDialog::Accepted)
        return;
    m_settings.setLastStExportSingleFile(options.singleFile());
    if (!options.singleFile())
        m_settings.setLastExportDialect(options.dialect());

    QString path;
    QString error;
    bool ok = false;
    if (options.singleFile()) {
        path = askSavePath(tr("Export Structured Text"), QStringLiteral("st"), tr("Structured Text (*.st)"));
        if (path.isEmpty())
            return;
        ok = writeStSingleFile(path, &error);
    } else {
        path = QFileDialog::getExistingDirectory(m_window, tr("Export Structured Text to a Folder"),
                                                 m_settings.lastExportDirectory());
        if (path.isEmpty())
            return;
        m_settings.setLastExportDirectory(path);
        ok = writeStFolder(path, options.dialect(), &error);
    }
    reportResult(ok, path, error);
}

void ExportActions::exportGGGenerator()
{
    if (!confirmGGGeneratorLosses(m_window, m_document.model()))
        return;
    const QString path = askSavePath(tr("Export GG-Generator JSON"), QStringLiteral("json"),
                                     tr("GG-Generator JSON (*.json)"));
    if (path.isEmpty())
        return;
    QString error;
    const bool ok = writeGGGenerator(path, &error);
    reportResult(ok, path, error);
}

void ExportActions::exportChart()
{
    const QString svg = tr("SVG picture (*.svg)");
    const QString png = tr("PNG image (*.png)");
    const QString pdf = tr("PDF document (*.pdf)");
    QString filter = svg;
    QString path = askSavePath(tr("Export Chart"), QString(), QStringList{svg, png, pdf}.join(QStringLiteral(";;")),
                               &filter);
    if (path.isEmpty())
        return;
    ChartExport::Format format = ChartExport::Format::Svg;
    if (!ChartExport::formatForPath(path, &format)) {
        // No known extension typed: the chosen filter decides.
        const QString suffix = filter == png ? QStringLiteral("png") : filter == pdf ? QStringLiteral("pdf")
                                                                                     : QStringLiteral("svg");
        path += '.' + suffix;
        ChartExport::formatForPath(path, &format);
    }
    QString error;
    const bool ok = writeChart(path, format, &error);
    reportResult(ok, path, error);
}

bool ExportActions::writeChart(const QString& path, ChartExport::Format format, QString* errorMessage) const
{
    const QString title = QString::fromStdString(m_document.model().settings().name);
    if (GrafcetScene* grafcet = m_grafcetInFront ? m_grafcetInFront() : nullptr) {
        GrafcetExport picture(*grafcet);
        picture.setTitle(tr("%1, nested GRAFCET of %2").arg(title, grafcet->stepId()));
        return picture.write(path, format, errorMessage);
    }
    if (m_packmlChart && m_document.model().templateKind() == core::TemplateKind::PackML) {
        PackmlChartExport chart(*m_packmlChart);
        chart.setTitle(title);
        return chart.write(path, format, errorMessage);
    }
    ChartExport chart(m_scene);
    chart.setTitle(title);
    return chart.write(path, format, errorMessage);
}

bool ExportActions::writeSpecification(const QString& path, QString* errorMessage) const
{
    return SpecificationExport(m_document).writePdf(path, errorMessage);
}

void ExportActions::exportSpecification()
{
    const QString path =
        askSavePath(tr("Export Specification"), QStringLiteral("pdf"), tr("PDF document (*.pdf)"), nullptr,
                    suggestedSpecificationName(m_document.filePath(), m_document.model()));
    if (!path.isEmpty())
        exportSpecificationTo(path);
}

// In slices on the GUI thread (the export draws the Document's own scenes):
// the event loop runs between two sections laid out and between two pages.
bool ExportActions::exportSpecificationTo(const QString& path)
{
    QProgressDialog progress(tr("Writing the specification…"), tr("Cancel"), 0, 1, m_window);
    progress.setObjectName(QStringLiteral("specificationProgress"));
    progress.setWindowTitle(tr("Export Specification"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setAutoReset(false);
    progress.setAutoClose(false);
    progress.setMinimumDuration(kProgressDelayMs);
    SpecificationExport specification(m_document);
    specification.setProgress([&progress](int done, int total) {
        progress.setMaximum(total);
        progress.setValue(done);
        QCoreApplication::processEvents();
        return !progress.wasCanceled();
    });
    QString error;
    bool cancelled = false;
    const bool ok = specification.writePdf(path, &error, &cancelled);
    progress.hide();
    if (cancelled)
        emit exported(tr("Export cancelled: %1 left unchanged").arg(QDir::toNativeSeparators(path)));
    else
        reportResult(ok, path, error);
    return ok;
}

void ExportActions::print()
{
    GrafcetScene* grafcet = m_grafcetInFront ? m_grafcetInFront() : nullptr;
    QPrinter printer(QPrinter::HighResolution);
    // The GEMMA sheet is wider than high; a GRAFCET goes down.
    printer.setPageOrientation(grafcet ? QPageLayout::Portrait : QPageLayout::Landscape);
    QPrintDialog dialog(&printer, m_window);
    dialog.setWindowTitle(tr("Print Chart"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    const QString title = QString::fromStdString(m_document.model().settings().name);
    bool printed = false;
    if (grafcet) {
        GrafcetExport picture(*grafcet);
        picture.setTitle(tr("%1, nested GRAFCET of %2").arg(title, grafcet->stepId()));
        printed = picture.print(printer);
    } else if (m_packmlChart && m_document.model().templateKind() == core::TemplateKind::PackML) {
        PackmlChartExport chart(*m_packmlChart);
        chart.setTitle(title);
        printed = chart.print(printer);
    } else {
        ChartExport chart(m_scene);
        chart.setTitle(title);
        printed = chart.print(printer);
    }
    if (!printed)
        QMessageBox::critical(m_window, tr("Print Chart"), tr("The printer could not be started."));
}

core::Dialect ExportActions::lastDialect() const
{
    return m_settings.lastExportDialect(m_document.model().settings().dialect);
}

QString ExportActions::askSavePath(const QString& title, const QString& suffix, const QString& filters,
                                   QString* selectedFilter, const QString& givenName)
{
    QString name = givenName;
    if (name.isEmpty()) {
        name = suggestedBaseName(m_document.filePath(), m_document.model());
        if (!suffix.isEmpty())
            name += '.' + suffix;
    }
    const QString start = QDir(m_settings.lastExportDirectory()).filePath(name);
    QString path = QFileDialog::getSaveFileName(m_window, title, start, filters, selectedFilter);
    if (path.isEmpty())
        return {};
    if (!suffix.isEmpty())
        path = withSuffix(path, suffix);
    m_settings.setLastExportDirectory(QFileInfo(path).absolutePath());
    return path;
}

void ExportActions::reportResult(bool ok, const QString& path, const QString& errorMessage)
{
    const QString shown = QDir::toNativeSeparators(path);
    if (ok) {
        emit exported(tr("Exported to %1").arg(shown));
        return;
    }
    QMessageBox::critical(m_window, tr("Export Failed"), tr("Could not write %1.").arg(shown) + "\n\n" + errorMessage);
}

} // namespace editor
