#include "core/codegen/stexport.h"

#include "core/formats/fileio.h"
#include "core/codegen/stgenerator.h"

#include <algorithm>

namespace core {

namespace {

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
    return project.globalListName.empty() ? std::string(kCodesysGlobalList) : project.globalListName;
}

std::string globalsText(const PlcProject& project)
{
    return project.dialect == Dialect::Iec ? formatConfiguration(project) : formatGlobals(project);
}

// Problems with the folder itself keep this export's own code.
Status asFolderProblem(Status status)
{
    if (status.code == "file.folder" || status.code == "file.not-folder")
        status.code = "stexport.folder";
    return status;
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

Status exportStFolder(const PlcProject& project, const std::string& folderPath, const FileWriter& writeFile)
{
    const std::vector<StFile> files = stFolderFiles(project);
    for (const StFile& file : files) {
        const std::string stem = file.name.substr(0, file.name.size() - 3);
        if (!isSafeFileStem(stem)) {
            return Status::failure("stexport.file-name",
                                   "cannot export \"" + file.name + "\": a POU or list name must be an IEC identifier");
        }
    }
    if (folderPath.empty())
        return Status::failure("stexport.folder", "no folder given for the Structured Text export");
    std::vector<FolderFile> contents;
    contents.reserve(files.size());
    for (const StFile& file : files)
        contents.push_back({file.name, file.text});
    return asFolderProblem(writeFolderAtomically(folderPath, contents, writeFile));
}

Status exportStSingleFile(const Model& model, const std::string& filePath)
{
    if (filePath.empty())
        return Status::failure("stexport.file-name", "no file given for the Structured Text export");
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    return writeFileAtomically(filePath, formatSingleFileIec(project));
}

} // namespace core
