#include "core/stexport.h"

#include "core/fileio.h"
#include "core/stgenerator.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace core {

namespace {

namespace fs = std::filesystem;

// File names come from POU and list names, which are IEC identifiers; a name
// that is not one could reach outside the folder, so it is refused.
bool isSafeFileStem(const std::string& stem)
{
    return !stem.empty() && std::all_of(stem.begin(), stem.end(), [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

std::string globalsFileStem(const PlcProject& project)
{
    if (project.dialect == Dialect::Iec)
        return "globals";
    return project.globalListName.empty() ? "GVL" : project.globalListName;
}

std::string globalsText(const PlcProject& project)
{
    return project.dialect == Dialect::Iec ? formatConfiguration(project) : formatGlobals(project);
}

Status prepareFolder(const std::string& folderPath)
{
    std::error_code error;
    const fs::path folder(folderPath);
    if (folderPath.empty())
        return Status::failure("stexport.folder", "no folder given for the Structured Text export");
    if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
        return Status::failure("stexport.folder",
                               "cannot export into \"" + folderPath + "\": it exists and is not a folder");
    }
    fs::create_directories(folder, error);
    if (error) {
        return Status::failure("stexport.folder",
                               "cannot create the folder \"" + folderPath + "\": " + error.message());
    }
    return Status::success();
}

} // namespace

std::vector<StFile> stFolderFiles(const PlcProject& project)
{
    std::vector<StFile> files;
    files.reserve(project.pous.size() + 1);
    for (const PlcPou& pou : project.pous)
        files.push_back({pou.name + ".st", formatPou(pou, project.dialect)});
    files.push_back({globalsFileStem(project) + ".st", globalsText(project)});
    return files;
}

Status exportStFolder(const PlcProject& project, const std::string& folderPath)
{
    const std::vector<StFile> files = stFolderFiles(project);
    for (const StFile& file : files) {
        const std::string stem = file.name.substr(0, file.name.size() - 3);
        if (!isSafeFileStem(stem)) {
            return Status::failure("stexport.file-name",
                                   "cannot export \"" + file.name + "\": a POU or list name must be an IEC identifier");
        }
    }
    if (Status prepared = prepareFolder(folderPath); !prepared)
        return prepared;
    for (const StFile& file : files) {
        if (Status written = writeFileAtomically((fs::path(folderPath) / file.name).string(), file.text); !written)
            return written;
    }
    return Status::success();
}

Status exportStSingleFile(const Model& model, const std::string& filePath)
{
    if (filePath.empty())
        return Status::failure("stexport.file-name", "no file given for the Structured Text export");
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    return writeFileAtomically(filePath, formatSingleFileIec(project));
}

} // namespace core
