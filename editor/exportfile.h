#pragma once

#include <QByteArray>
#include <QString>

namespace editor {

// Writes an exported picture or document through core's atomic writer, so a
// failed export never leaves half a file in place of a good one. False with
// the reason in *errorMessage.
bool writeExportFile(const QString& path, const QByteArray& bytes, QString* errorMessage);

} // namespace editor
