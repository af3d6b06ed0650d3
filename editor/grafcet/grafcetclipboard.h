#pragma once

// The GRAFCET steps on the system clipboard, so that Paste works in another
// tab, another window or another GG Studio: Copy puts the fragment there as
// kMimeType (JSON, core/formats/grafcetfragmentjson.h) with a plain-text
// rendering for other programs (a mail, a report). What is read back was
// possibly written by anyone: a damaged fragment comes back as a message.

#include "core/model/grafcetediting.h"

#include <QCoreApplication>
#include <QString>

#include <variant>

class QMimeData;

namespace editor {

class GrafcetClipboard {
    Q_DECLARE_TR_FUNCTIONS(GrafcetClipboard)

public:
    static inline const QString kMimeType = QStringLiteral("application/x-ggstudio-grafcet-fragment");

    static void put(const core::GrafcetFragment& fragment);
    // Whether the clipboard holds a fragment (sound or not: Paste says which).
    static bool holdsFragment();
    // The clipboard's fragment, or why it cannot be pasted (for the status bar).
    static std::variant<core::GrafcetFragment, QString> fragment();

    // "Step 2 — comment", its actions, "T1 (1 → 2): receptivity", one per line.
    static QString plainText(const core::GrafcetFragment& fragment);
};

} // namespace editor
