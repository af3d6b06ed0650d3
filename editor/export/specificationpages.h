#pragma once

#include "editor/export/specificationexport.h"
#include "editor/export/specificationflow.h"
#include "editor/export/specificationtable.h"
#include "editor/selection.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QGraphicsScene>
#include <QList>
#include <QSizeF>
#include <QString>
#include <QStringList>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QPagedPaintDevice;

namespace core {
class Model;
struct PlcPou;
} // namespace core

namespace editor {
class Document;
}

namespace editor::specification {

// An entry of the title page's contents; its page is known once the
// section is planned, before anything is painted.
struct ContentsEntry {
    QString text;
    bool sub = false;
    int page = 0;
};

// The specification of one model on the pages of one PDF: planned section
// by section into a Flow, then painted page by page with the running
// header and the foot, which know the page count. What both templates'
// specifications share: the title page's frame, the tables, the variables,
// the nested GRAFCETs' pages and the code outline; each template's class
// gives its sections.
class SpecificationPages {
    Q_DECLARE_TR_FUNCTIONS(SpecificationExport)

public:
    SpecificationPages(Document& document, const QDateTime& date, QPagedPaintDevice& device, const QSizeF& printable,
                       double dotsPerPoint);
    virtual ~SpecificationPages() = default;
    SpecificationPages(const SpecificationPages&) = delete;
    SpecificationPages& operator=(const SpecificationPages&) = delete;

    // Lays the sections out, then draws every page, telling `progress`
    // after each; false when it cancelled.
    bool write(QPainter& painter, const SpecificationExport::Progress& progress);

protected:
    using Section = std::function<void()>;
    // The sections in order, each planning its pages into the flow.
    virtual std::vector<Section> sections() = 0;

    // The running header's section names: the model's name is wrapped
    // clear of the widest. Called once, by the constructor of the template's class.
    void setSectionNames(const QStringList& names);

    std::size_t addContentsEntry(const QString& text, bool sub = false);
    void startsHere(std::size_t entry) { (*m_contents)[entry].page = m_flow->pageNumber(); }
    int pageOf(std::size_t entry) const { return (*m_contents)[entry].page; }

    // The title page: the model's name, `subtitle`, the file and date, then
    // `facts` (label, value), the checks' verdict, and the contents.
    void planTitlePage(const QString& section, const QString& subtitle, const QList<QStringList>& facts);
    // The facts both templates give: the PLC task cycle and the code dialect.
    QList<QStringList> cycleAndDialectFacts() const;
    // A section of the tables: its heading, what it lists, the table (or
    // `empty` when it has no row).
    void planTable(std::size_t entry, const QString& heading, const QString& intro, const Table& table,
                   const QString& empty);
    void planVariables(std::size_t entry);

    // A nested GRAFCET from a new page: its heading band (`title`, then
    // `facts`), its drawing over as many pages as it needs (the following
    // ones headed `continued`), its steps' comments under `stepsHeading`.
    struct GrafcetPart {
        QString key; // in the model's GRAFCET storage
        QString title;
        QStringList facts;
        QString continued;
        QString stepsHeading;
        QString functionBlock; // its function block's name, in the facts after the counts
        std::vector<std::size_t> contentsEntries; // that start on its first page
    };
    void planGrafcet(const QString& section, const GrafcetPart& part);

    // The outline of the generated code: `intro` (%1: the program's name), the task, each POU with
    // `describe`'s sentence and its interface, the globals the generator
    // adds; `variablesEntry` is where the declared variables are listed.
    using PouDescription = std::function<QString(const core::PlcPou& pou, const QString& program)>;
    void planCode(const QString& section, std::size_t entry, std::size_t variablesEntry, const QString& intro,
                  const PouDescription& describe);

    double bodyLine() const { return m_style.metrics(TextStyle::Body).lineSpacing(); }
    int errorCount() const;
    // A scene the pages draw, kept alive until they are painted.
    template <typename Scene> Scene& keepScene(std::unique_ptr<Scene> scene)
    {
        Scene& kept = *scene;
        m_scenes.push_back(std::move(scene));
        return kept;
    }

    Document& m_document;
    const core::Model& m_model;
    Style m_style;
    double m_width; // of a portrait page's body
    QString m_modelName;
    Selection m_selection; // empty: the scenes draw nothing selected
    std::map<QString, int> m_grafcetPages; // the first page of each GRAFCET, by key

private:
    // Every page; false when `pageDone` returned false after one.
    bool paint(QPainter& painter, const std::function<bool()>& pageDone) const;

    QDateTime m_date;
    QPagedPaintDevice& m_device;
    QSizeF m_printable;
    QStringList m_headerLines; // the model's name, wrapped clear of the section
    double m_bodyTop = 0;
    std::shared_ptr<std::vector<ContentsEntry>> m_contents;
    // Declared before the flow, whose blocks refer to them.
    std::vector<std::unique_ptr<QGraphicsScene>> m_scenes;

protected:
    std::optional<Flow> m_flow;
};

} // namespace editor::specification
