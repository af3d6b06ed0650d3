#pragma once

// Helpers of the model file tests: a model that uses every feature both file
// formats express, and a scratch folder that cleans up after itself.

#include "core/model/model.h"

#include <filesystem>
#include <string>
#include <vector>

namespace filetests {

// Variables of every kind, steps with changed types, a moved initial step,
// hidden steps and transitions, conditions, changed orders, negations and
// tokens of both polarities: everything GG-Generator files can hold.
core::Model richGGModel();

// richGGModel() plus what only the native format holds: name, settings,
// step and variable comments (with quotes, newlines and non-ASCII text).
core::Model richNativeModel();

std::string readBinaryFile(const std::filesystem::path& path);
void writeBinaryFile(const std::filesystem::path& path, const std::string& contents);

#ifndef _WIN32
// Entries that are not regular files, for the saves that must refuse them.
void makeFifo(const std::filesystem::path& path);
void makeSocket(const std::filesystem::path& path); // a bound UNIX socket, left on disk
// A character device a test may aim a write at without risk: a private node
// with /dev/null's numbers where that is allowed (root, who could replace
// /dev/null itself), else /dev/null (which others cannot replace).
std::filesystem::path harmlessCharacterDevice(const std::filesystem::path& folder);
#endif

// A fresh folder under the system temporary folder, removed with its
// contents when the object dies.
class ScratchFolder {
public:
    ScratchFolder();
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return m_path; }
    std::filesystem::path file(const std::string& name) const { return m_path / name; }
    // Names of the entries, sorted.
    std::vector<std::string> entries() const;

private:
    std::filesystem::path m_path;
};

} // namespace filetests
