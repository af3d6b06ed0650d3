#include "core/fileio.h"

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
    if (::rename(temporary.c_str(), target.c_str()) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        return Status::failure("file.rename", "cannot save \"" + path + "\": " + errnoText(error));
    }
    syncDirectory(directory);
    return Status::success();
}

#endif

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
    std::error_code error;
    if (fs::is_directory(target, error))
        return writeFailure(path, "a folder of that name exists");
    return writeAndReplace(target, path, contents);
}

} // namespace core
