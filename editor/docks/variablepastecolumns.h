#pragma once

#include <QStringList>

#include <optional>

namespace editor {

// Which cell of a row pasted into the Variables table holds which field
// (-1: none). Without a header the order is fixed: name, type, default,
// comment, kind (the order Copy writes, documented in docs/user-guide.md).
struct VariablePasteColumns {
    int name = 0;
    int type = 1;
    int defaultValue = 2;
    int comment = 3;
    int kind = 4;
    // The header names a kind column: its cells must then be kinds.
    bool kindDeclared = false;
};

// The columns a first pasted line names when it is a header: each of its
// non-empty cells a column title of the table, in any UI language, or one
// of the English names Copy writes, with the name among them. Nullopt when
// the line is data.
std::optional<VariablePasteColumns> headerColumns(const QStringList& cells);

} // namespace editor
