#pragma once

// A folder made to refuse new files for the time of a test: the failure
// paths of the atomic writes (core's file tests, the editor's exports).

#include <filesystem>

namespace testsupport {

#ifndef _WIN32
// chmod for ordinary users; the immutable attribute for root, who ignores
// permission bits. Undone when the object dies.
class ReadOnlyFolder {
public:
    explicit ReadOnlyFolder(const std::filesystem::path& path);
    ~ReadOnlyFolder();
    ReadOnlyFolder(const ReadOnlyFolder&) = delete;
    ReadOnlyFolder& operator=(const ReadOnlyFolder&) = delete;

    // The precondition of the test: can nothing be created in the folder?
    bool effective() const;

private:
    std::filesystem::path m_path;
    bool m_immutable = false;
};
#endif

} // namespace testsupport
