#include "editor/export/specificationexport.h"

#include "editor/document.h"
#include "editor/export/exportfile.h"
#include "editor/export/gemmaspecification.h"
#include "editor/export/packmlspecification.h"
#include "editor/text/displaytext.h"

#include "core/model/model.h"

#include <QPagedPaintDevice>

#include <memory>

namespace editor {

namespace {

// The specification of the model's template.
std::unique_ptr<specification::SpecificationPages> makePages(Document& document, const QDateTime& date,
                                                             QPagedPaintDevice& device, const QSizeF& printable,
                                                             double dotsPerPoint)
{
    if (document.model().packml()) {
        return std::make_unique<specification::PackmlSpecificationPages>(document, date, device, printable,
                                                                         dotsPerPoint);
    }
    return std::make_unique<specification::GemmaSpecificationPages>(document, date, device, printable,
                                                                    dotsPerPoint);
}

} // namespace

SpecificationExport::SpecificationExport(Document& document)
    : m_document(document)
{
}

QString SpecificationExport::grafcetTitle(const QString& stepId)
{
    return specification::GemmaSpecificationPages::stateLabel(stepId);
}

QString SpecificationExport::suggestedFileName(const QString& baseName)
{
    //: the specification's title and the file name it is saved under; %1 is the model's name
    return tr("%1 specification").arg(baseName) + QStringLiteral(".pdf");
}

bool SpecificationExport::writePdf(const QString& path, QString* errorMessage, bool* cancelled) const
{
    bool stopped = false;
    const QString title
        = tr("%1 specification").arg(withVisibleControls(QString::fromStdString(m_document.model().settings().name)));
    const QDateTime date = m_date.isValid() ? m_date : QDateTime::currentDateTime();
    const bool ok = PictureFile::writePdf(
        path, title, QPageLayout::Portrait,
        [&](QPainter& painter, QPagedPaintDevice& device, const QSizeF& printable, double dotsPerPoint) {
            const std::unique_ptr<specification::SpecificationPages> pages
                = makePages(m_document, date, device, printable, dotsPerPoint);
            stopped = !pages->write(painter, m_progress);
        },
        errorMessage, [&stopped] { return stopped; });
    if (cancelled)
        *cancelled = stopped;
    return ok;
}

} // namespace editor