#pragma once

// Reading and writing whole files safely: a size limit checked before
// anything is read, UTF-8 validation that says where the first bad byte is,
// and atomic replacement so a failed save never damages the existing file
// (nor anything that is not a regular file: a device, a FIFO, a socket).

#include "core/model/status.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

// 1-based line and column; columns count characters (UTF-8 code points), so
// they match what an editor shows for valid text.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};

// The position of a byte offset in the text (offsets past the end give the
// position just after the last character).
TextPosition textPosition(std::string_view text, std::size_t offset);
std::string describePosition(TextPosition position); // "line 3, column 14"

struct Utf8Problem {
    std::size_t offset = 0; // of the first byte that is not valid UTF-8
    TextPosition position;
};

// nullopt when the whole text is valid UTF-8 (overlong forms, surrogates and
// code points above U+10FFFF are invalid).
std::optional<Utf8Problem> findInvalidUtf8(std::string_view text);

// Reads a regular file of at most maxBytes. The size is checked before any
// byte is read, so a huge file costs nothing. Codes: "file.open",
// "file.not-regular", "file.too-large", "file.read".
Status readFileLimited(const std::string& path, std::uintmax_t maxBytes, std::string& contents);

// Writes the contents to a temporary file beside the target, flushes it to
// disk and renames it over the target. On any failure the previous file is
// untouched and the temporary file is removed. A symbolic link is followed:
// the file it points to is replaced, the link stays. Only a regular file is
// ever replaced: a target that is a folder, a device, a FIFO or a socket (or
// a link to one) is refused before anything is written. Codes:
// "file.not-regular", "file.write", "file.rename".
Status writeFileAtomically(const std::string& path, std::string_view contents);

// Success when a folder may be written at the path: nothing is there yet,
// or a folder (or a link to one) is. Code "file.not-folder".
Status checkFolderTarget(const std::string& folderPath);

// How one file is written; writeFolderAtomically takes another one only in
// tests, to make the n-th write fail as a full disk would.
using FileWriter = std::function<Status(const std::string& path, std::string_view contents)>;

struct FolderFile {
    std::string name; // a plain file name, no folder part
    std::string_view contents;
};

// Puts the files into the folder all or nothing: they are written to a new
// sibling folder, the entries of the old folder with other names are carried
// over (hard links, or copies where the file system has none), then the new
// folder is renamed in place of the old one, which is removed. On any failure
// the old folder is as it was. The folder (and its parents) is created when
// missing; a symbolic link to a folder is followed. An entry of the old folder
// that one of the files would replace must be a regular file. Codes:
// "file.folder", "file.not-folder", "file.not-regular", those of the writer.
Status writeFolderAtomically(const std::string& folderPath, const std::vector<FolderFile>& files,
                             const FileWriter& writeFile = writeFileAtomically);

// "83886080 bytes (80.0 MiB)".
std::string describeByteSize(std::uintmax_t bytes);

} // namespace core
