#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QString>

#include <functional>

namespace editor {

class Document;

// The specification of the whole model as one PDF, the document an engineer
// hands over and a teacher hands out. A4, the model's name and the section
// at the top of every page, the page number at the bottom:
// - a title page: the model's name, its file, the date, its settings, the
//   checks' verdict and the contents;
// - the GEMMA chart on a landscape page, as Export Chart draws it (hidden
//   elements left out), its Conditions list under it or on the next pages;
// - the visible states (id, official name in the UI language, type,
//   nested GRAFCET steps, comment), the effective transitions (priority,
//   condition, tokens) and the variables (name, kind, type, default,
//   comment) as tables;
// - the machine, when the model has one: its components with their kind,
//   wiring and settings, then the Machine tab's schematic at rest;
// - each nested GRAFCET that generates code, from a new page headed
//   "F1 Normal production", drawn as GrafcetExport draws it (over several
//   pages, broken between steps and transitions, when too tall), then its
//   steps' comments;
// - the outline of the generated code: the task, the POUs with their
//   interfaces (inputs, outputs, instances, the globals they read, their
//   locals) and the globals the generator adds.
// A PackML model's specification has its own sections (the chart of each
// unit mode, the commands, the modes, each own GRAFCET headed
// "Production · Execute"; docs/packml.md, "Specification PDF").
// Nothing is cut short: texts wrap (a word wider than its column between
// its characters), tables break between rows and repeat their header, a row
// taller than a page breaks between its lines.
class SpecificationExport {
    Q_DECLARE_TR_FUNCTIONS(SpecificationExport)

public:
    explicit SpecificationExport(Document& document);

    // The date on the title page and the pages' foot; now unless set.
    void setDate(const QDateTime& date) { m_date = date; }

    // Called between the parts of the work (each section laid out, each
    // page drawn) with the parts done and their total so far (the pages are
    // counted once laid out); returning false cancels the export.
    using Progress = std::function<bool(int done, int total)>;
    void setProgress(Progress progress) { m_progress = std::move(progress); }

    // Writes the PDF through the atomic writer: a failure or a cancel leaves
    // the file as it was. False with a message for the user, or with
    // *cancelled (when given) set and no message when the progress cancelled.
    bool writePdf(const QString& path, QString* errorMessage, bool* cancelled = nullptr) const;

    // The heading of a nested GRAFCET's first page: "F1 Normal production".
    static QString grafcetTitle(const QString& stepId);
    // The file name the export suggests: "Drilling cell DC-1 specification.pdf".
    static QString suggestedFileName(const QString& baseName);

private:
    Document& m_document;
    QDateTime m_date;
    Progress m_progress;
};

} // namespace editor
