#include "editor/exportfile.h"

#include "core/formats/fileio.h"

#include <QFile>

#include <string_view>

namespace editor {

bool writeExportFile(const QString& path, const QByteArray& bytes, QString* errorMessage)
{
    const core::Status status = core::writeFileAtomically(QFile::encodeName(path).toStdString(),
                                                          std::string_view(bytes.constData(), bytes.size()));
    if (!status && errorMessage)
        *errorMessage = QString::fromStdString(status.message);
    return status.ok;
}

} // namespace editor
