#include "core/formats/fileio.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#ifdef _WIN32
#include <process.h>
#else
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace fs = std::filesystem;

namespace core {

namespace {

bool isContinuationByte(unsigned char byte)
{
    return (byte & 0xC0u) == 0x80u;
}

// Length of the valid UTF-8 sequence at text[i], or 0 when it is invalid.
// The ranges of the second byte exclude overlong forms, surrogates and
// code points above U+10FFFF (RFC 3629, table 3-7 of the Unicode standard).
std::size_t validSequenceLength(std::string_view text, std::size_t i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
    const unsigned char lead = byte(0);
    if (lead < 0x80u)
        return 1;
    std::size_t length = 0;
    unsigned char low = 0x80u;
    unsigned char high = 0xBFu;
    if (lead >= 0xC2u && lead <= 0xDFu) {
        length = 2;
    } else if (lead >= 0xE0u && lead <= 0xEFu) {
        length = 3;
        if (lead == 0xE0u)
            low = 0xA0u;
        else if (lead == 0xEDu)
            high = 0x9Fu;
    } else if (lead >= 0xF0u && lead <= 0xF4u) {
        length = 4;
        if (lead == 0xF0u)
            low = 0x90u;
        else if (lead == 0xF4u)
            high = 0x8Fu;
    } else {
        return 0;
    }
    if (i + length > text.size())
        return 0;
    if (byte(1) < low || byte(1) > high)
        return 0;
    for (std::size_t k = 2; k < length; ++k) {
        if (!isContinuationByte(byte(k)))
            return 0;
    }
    return length;
}

std::string errnoText(int error)
{
    return std::generic_category().message(error);
}

Status writeFailure(const std::string& path, const std::string& why)
{
    return Status::failure("file.write", "cannot save \"" + path + "\": " + why);
}

// The file a save should replace: the target of a symbolic link, so the
// link survives the save.
fs::path resolveTarget(const std::string& path)
{
    std::error_code error;
    const fs::path target(path);
    if (fs::is_symlink(fs::symlink_status(target, error))) {
        fs::path resolved = fs::canonical(target, error);
        if (!error)
            return resolved;
    }
    return target;
}

// What stands at a path, as a save names it: "a named pipe (FIFO)".
std::string describeFileType(fs::file_type type)
{
    switch (type) {
    case fs::file_type::regular:
        return "a file";
    case fs::file_type::directory:
        return "a folder";
    case fs::file_type::symlink:
        return "a symbolic link";
    case fs::file_type::fifo:
        return "a named pipe (FIFO)";
    case fs::file_type::character:
        return "a character device";
    case fs::file_type::block:
        return "a block device";
    case fs::file_type::socket:
        return "a socket";
    default:
        return "something other than a file";
    }
}

// A save may only replace a regular file: renaming over a device node, a
// FIFO or a socket would destroy it (root may even replace /dev/null), and
// what the user meant was to write into it, which a save cannot promise to
// do atomically. `target` is the path with its links followed.
Status checkReplaceable(const std::string& path, const fs::path& target)
{
    std::error_code error;
    const fs::file_type type = fs::status(target, error).type();
    // Absent (or unreadable: the write then says why) is no reason to refuse.
    if (type == fs::file_type::regular || type == fs::file_type::not_found || type == fs::file_type::none)
        return Status::success();
    const std::string what = describeFileType(type);
    const std::string why = target == fs::path(path)
        ? "it is " + what + (type == fs::file_type::directory ? ", not a file" : ", not a regular file")
        : "it links to \"" + target.string() + "\", which is " + what + ", not a regular file";
    return Status::failure("file.not-regular", "cannot save \"" + path + "\": " + why);
}

std::string temporaryName(const fs::path& target, int attempt)
{
    static std::atomic<unsigned> counter{0};
#ifdef _WIN32
    const long pid = static_cast<long>(_getpid());
#else
    const long pid = static_cast<long>(::getpid());
#endif
    return "." + target.filename().string() + ".tmp-" + std::to_string(pid) + "-"
        + std::to_string(counter.fetch_add(1)) + "-" + std::to_string(attempt);
}

#ifdef _WIN32

void syncDirectory(const fs::path&) {}

// The owner of a folder is not carried over on Windows.
void copyOwner(const fs::path&, const fs::path&) {}

// No fsync or mode bits here: the standard library is all we rely on.
Status writeAndReplace(const fs::path& target, const std::string& path, std::string_view contents)
{
    const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const fs::path temporary = directory / temporaryName(target, 0);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        out.flush();
        if (!out) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            return writeFailure(path, "cannot write a temporary file in the folder");
        }
    }
    if (Status replaceable = checkReplaceable(path, target); !replaceable) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return replaceable;
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return Status::failure("file.rename", "cannot save \"" + path + "\": " + error.message());
    }
    return Status::success();
}

#else

// A descriptor that closes itself; close() reports the error a delayed
// write may surface only then.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : m_fd(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    int get() const { return m_fd; }
    int close()
    {
        const int result = ::close(m_fd);
        m_fd = -1;
        return result;
    }

private:
    int m_fd;
};

int createExclusive(const fs::path& directory, const fs::path& target, fs::path& temporary)
{
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporary = directory / temporaryName(target, attempt);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

bool writeAll(int fd, std::string_view contents)
{
    std::size_t written = 0;
    while (written < contents.size()) {
        const ssize_t result = ::write(fd, contents.data() + written, contents.size() - written);
        if (result < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        written += static_cast<std::size_t>(result);
    }
    return true;
}

// Makes the rename itself durable; a failure here does not undo the save.
void syncDirectory(const fs::path& directory)
{
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

// Best effort: root exporting into a user's folder should leave it theirs.
void copyOwner(const fs::path& from, const fs::path& to)
{
    struct stat existing {};
    if (::stat(from.c_str(), &existing) == 0 && ::chown(to.c_str(), existing.st_uid, existing.st_gid) != 0) {
        // Not allowed for an ordinary user giving a folder away; the folder stays theirs anyway.
    }
}

Status writeAndReplace(const fs::path& target, const std::string& path, std::string_view contents)
{
    const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
    fs::path temporary;
    FileDescriptor fd(createExclusive(directory, target, temporary));
    if (fd.get() < 0)
        return writeFailure(path, "cannot create a temporary file in \"" + directory.string() + "\": " + errnoText(errno));

    // Keep the permissions of the file being replaced.
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0)
        ::fchmod(fd.get(), existing.st_mode & 07777);

    const auto fail = [&](const std::string& why) {
        ::unlink(temporary.c_str());
        return writeFailure(path, why);
    };
    if (!writeAll(fd.get(), contents))
        return fail(errnoText(errno));
    if (::fsync(fd.get()) != 0)
        return fail(errnoText(errno));
    if (fd.close() != 0)
        return fail(errnoText(errno));
    // Checked again: the target may have become a FIFO while we wrote.
    if (Status replaceable = checkReplaceable(path, target); !replaceable) {
        ::unlink(temporary.c_str());
        return replaceable;
    }
    if (::rename(temporary.c_str(), target.c_str()) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        return Status::failure("file.rename", "cannot save \"" + path + "\": " + errnoText(error));
    }
    syncDirectory(directory);
    return Status::success();
}

#endif

Status folderFailure(const std::string& code, const std::string& folderPath, const std::string& why)
{
    return Status::failure(code, "cannot write the folder \"" + folderPath + "\": " + why);
}

bool isPlainFileName(const std::string& name)
{
    return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos
        && name.find('\\') == std::string::npos;
}

// The folder to replace: links followed (the link stays, as for files), no
// "." or trailing separator, so that it has a name and a parent to rename in.
fs::path resolveFolder(const std::string& folderPath)
{
    std::error_code error;
    fs::path folder = fs::weakly_canonical(fs::absolute(folderPath, error), error);
    if (error)
        folder = fs::absolute(folderPath, error).lexically_normal();
    if (folder.filename().empty())
        folder = folder.parent_path();
    return folder;
}

// Each file may replace only a regular file of the old folder. A link is
// refused too: writing through it would change a file outside the folder
// before the swap, so the export would no longer be all or nothing.
Status checkReplacedEntries(const std::string& folderPath, const fs::path& folder, const std::vector<FolderFile>& files)
{
    for (const FolderFile& file : files) {
        std::error_code error;
        const fs::file_type type = fs::symlink_status(folder / file.name, error).type();
        if (type == fs::file_type::regular || type == fs::file_type::not_found)
            continue;
        const std::string shown = (fs::path(folderPath) / file.name).string();
        const std::string what = describeFileType(type);
        return Status::failure("file.not-regular", "cannot save \"" + shown + "\": it is " + what
            + (type == fs::file_type::symlink ? "; the folder export replaces only the folder's own files"
                                              : ", not a regular file"));
    }
    return Status::success();
}

// A sibling of the folder named after it that does not exist yet.
fs::path unusedSibling(const fs::path& folder, const std::string& tag)
{
    for (int attempt = 0;; ++attempt) {
        fs::path candidate = folder.parent_path() / temporaryName(folder.filename().concat("." + tag), attempt);
        std::error_code error;
        if (!fs::exists(fs::symlink_status(candidate, error)))
            return candidate;
    }
}

fs::path createStagingFolder(const fs::path& folder, std::error_code& error)
{
    for (int attempt = 0; attempt < 100; ++attempt) {
        fs::path staging = unusedSibling(folder, "new");
        if (fs::create_directory(staging, error))
            return staging;
        if (error)
            return {};
    }
    error = std::make_error_code(std::errc::file_exists);
    return {};
}

// Hard links cost no space and keep the very same files; where the file
// system has none, a copy.
std::error_code linkOrCopy(const fs::path& from, const fs::path& to)
{
    using options = fs::copy_options;
    std::error_code error;
    fs::copy(from, to, options::recursive | options::copy_symlinks | options::create_hard_links, error);
    if (!error)
        return error;
    std::error_code ignored;
    fs::remove_all(to, ignored);
    error.clear();
    fs::copy(from, to, options::recursive | options::copy_symlinks, error);
    return error;
}

// The user's own entries of the old folder go into the new one too.
Status carryOverEntries(const std::string& folderPath, const fs::path& folder, const fs::path& staging,
                        const std::vector<FolderFile>& files)
{
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        const bool replaced =
            std::any_of(files.begin(), files.end(), [&](const FolderFile& file) { return file.name == name; });
        if (replaced)
            continue;
        if (std::error_code copied = linkOrCopy(it->path(), staging / name)) {
            return folderFailure("file.folder", folderPath, "cannot keep \"" + name + "\" in the new folder: "
                + copied.message() + "; nothing was changed");
        }
    }
    if (error)
        return folderFailure("file.folder", folderPath, "cannot list the folder: " + error.message());
    std::error_code ignored;
    fs::permissions(staging, fs::status(folder, ignored).permissions(), ignored);
    copyOwner(folder, staging);
    return Status::success();
}

// The writer's message names the staging folder: name the user's instead.
Status renamedFailure(Status status, const fs::path& staged, const fs::path& shown)
{
    const std::string from = staged.string();
    const std::string to = shown.string();
    for (std::size_t at = status.message.find(from); at != std::string::npos; at = status.message.find(from, at + to.size()))
        status.message.replace(at, from.size(), to);
    status.message += "; nothing was changed";
    return status;
}

Status writeStagedFiles(const std::string& folderPath, const fs::path& staging, const std::vector<FolderFile>& files,
                        const FileWriter& writeFile)
{
    for (const FolderFile& file : files) {
        const fs::path staged = staging / file.name;
        if (Status written = writeFile(staged.string(), file.contents); !written)
            return renamedFailure(written, staged, fs::path(folderPath) / file.name);
    }
    return Status::success();
}

// Two renames: the old folder away, the new one in; the old one is put back
// when the second fails.
Status swapFolders(const std::string& folderPath, const fs::path& folder, const fs::path& staging, bool replacing)
{
    std::error_code error;
    if (!replacing) {
        fs::rename(staging, folder, error);
        return error ? folderFailure("file.rename", folderPath, error.message()) : Status::success();
    }
    const fs::path old = unusedSibling(folder, "old");
    fs::rename(folder, old, error);
    if (error)
        return folderFailure("file.rename", folderPath, "cannot move the old folder aside: " + error.message());
    fs::rename(staging, folder, error);
    if (error) {
        std::error_code ignored;
        fs::rename(old, folder, ignored);
        return folderFailure("file.rename", folderPath, error.message() + "; nothing was changed");
    }
    // The new set is in place: an old folder that cannot be removed is litter, not a failure.
    std::error_code ignored;
    fs::remove_all(old, ignored);
    return Status::success();
}

} // namespace

TextPosition textPosition(std::string_view text, std::size_t offset)
{
    TextPosition position;
    const std::size_t end = offset < text.size() ? offset : text.size();
    // Editors do not show a byte order mark: it takes no column.
    const std::size_t start = text.substr(0, 3) == "\xEF\xBB\xBF" && end >= 3 ? 3 : 0;
    for (std::size_t i = start; i < end; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++position.line;
            position.column = 1;
        } else if (!isContinuationByte(byte)) {
            ++position.column;
        }
    }
    return position;
}

std::string describePosition(TextPosition position)
{
    return "line " + std::to_string(position.line) + ", column " + std::to_string(position.column);
}

std::optional<Utf8Problem> findInvalidUtf8(std::string_view text)
{
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t length = validSequenceLength(text, i);
        if (length == 0)
            return Utf8Problem{i, textPosition(text, i)};
        i += length;
    }
    return std::nullopt;
}

std::string describeByteSize(std::uintmax_t bytes)
{
    std::string text = std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
    if (bytes < 1024)
        return text;
    const bool mebibytes = bytes >= 1024 * 1024;
    const double value = static_cast<double>(bytes) / (mebibytes ? 1024.0 * 1024.0 : 1024.0);
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, " (%.1f %s)", value, mebibytes ? "MiB" : "KiB");
    return text + buffer;
}

Status readFileLimited(const std::string& path, std::uintmax_t maxBytes, std::string& contents)
{
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error || !fs::exists(status))
        return Status::failure("file.open", "cannot open the file: " + (error ? error.message() : errnoText(ENOENT)));
    if (fs::is_directory(status))
        return Status::failure("file.not-regular", "this is a folder, not a file");
    if (!fs::is_regular_file(status))
        return Status::failure("file.not-regular", "this is not a regular file");

    const std::uintmax_t size = fs::file_size(path, error);
    if (error)
        return Status::failure("file.open", "cannot read the size of the file: " + error.message());
    const auto tooLarge = [&](std::uintmax_t bytes) {
        return Status::failure("file.too-large", "the file is " + describeByteSize(bytes)
            + "; files larger than " + describeByteSize(maxBytes) + " are not read");
    };
    if (size > maxBytes)
        return tooLarge(size);

    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Status::failure("file.open", "cannot open the file: " + errnoText(errno));
    // The file may grow between the size check and the read: never take in
    // more than the limit.
    std::string data;
    data.reserve(static_cast<std::size_t>(size));
    char buffer[64 * 1024];
    while (in) {
        in.read(buffer, sizeof buffer);
        data.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (data.size() > maxBytes)
            return tooLarge(data.size());
    }
    if (in.bad())
        return Status::failure("file.read", "cannot read the file: " + errnoText(errno));
    contents = std::move(data);
    return Status::success();
}

Status writeFileAtomically(const std::string& path, std::string_view contents)
{
    if (path.empty())
        return writeFailure(path, "no file name given");
    const fs::path target = resolveTarget(path);
    if (Status replaceable = checkReplaceable(path, target); !replaceable)
        return replaceable;
    return writeAndReplace(target, path, contents);
}

Status checkFolderTarget(const std::string& folderPath)
{
    std::error_code error;
    const fs::file_type type = fs::status(folderPath, error).type();
    if (type == fs::file_type::directory || type == fs::file_type::not_found || type == fs::file_type::none)
        return Status::success();
    return Status::failure("file.not-folder",
                           "cannot write into \"" + folderPath + "\": it is " + describeFileType(type) + ", not a folder");
}

Status writeFolderAtomically(const std::string& folderPath, const std::vector<FolderFile>& files,
                             const FileWriter& writeFile)
{
    if (folderPath.empty())
        return Status::failure("file.folder", "no folder given");
    for (const FolderFile& file : files) {
        if (!isPlainFileName(file.name))
            return folderFailure("file.folder", folderPath, "\"" + file.name + "\" is not a plain file name");
    }
    if (Status target = checkFolderTarget(folderPath); !target)
        return target;
    const fs::path folder = resolveFolder(folderPath);
    if (folder.filename().empty())
        return folderFailure("file.folder", folderPath, "a file system's root cannot be replaced");
    std::error_code error;
    const bool replacing = fs::is_directory(folder, error);
    if (replacing) {
        if (Status entries = checkReplacedEntries(folderPath, folder, files); !entries)
            return entries;
    } else if (fs::create_directories(folder.parent_path(), error); error) {
        return folderFailure("file.folder", folderPath, "cannot create the folder \"" + folder.parent_path().string()
            + "\": " + error.message());
    }

    const fs::path staging = createStagingFolder(folder, error);
    if (staging.empty()) {
        return folderFailure("file.folder", folderPath, "cannot create a temporary folder in \""
            + folder.parent_path().string() + "\": " + error.message());
    }
    Status result = writeStagedFiles(folderPath, staging, files, writeFile);
    if (result && replacing)
        result = carryOverEntries(folderPath, folder, staging, files);
    if (result)
        result = swapFolders(folderPath, folder, staging, replacing);
    if (!result) {
        std::error_code ignored;
        fs::remove_all(staging, ignored);
        return result;
    }
    syncDirectory(folder.parent_path());
    return Status::success();
}

} // namespace core
