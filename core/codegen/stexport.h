#pragma once

// Plain Structured Text export: a folder with one .st file per POU and one
// for the globals (what a PLC tool imports file by file), or one IEC
// 61131-3 file an IEC compiler builds directly.

#include "core/formats/fileio.h"
#include "core/model/model.h"
#include "core/codegen/plcproject.h"
#include "core/model/status.h"

#include <string>
#include <vector>

namespace core {

struct StFile {
    std::string name; // "GEMMA.st", "F1_FB.st", "globals.st", "GVL.st"
    std::string text;
};

// The files of the folder export, in order: the POUs (GEMMA first), then the
// globals: IEC "globals.st" holds the CONFIGURATION with its VAR_GLOBAL, the
// resource and the task; CODESYS "<GVL>.st" the qualified_only global list.
std::vector<StFile> stFolderFiles(const PlcProject& project);

// Writes stFolderFiles into the folder, creating it (and its parents) when
// needed, all or nothing (writeFolderAtomically): after a failure the folder
// holds the old set of files, after success the new one. Other entries of
// the folder are kept. writeFile is for tests only (a write that fails).
// Codes: "stexport.folder", "stexport.file-name", "file.not-regular" and
// those of writeFileAtomically.
Status exportStFolder(const PlcProject& project, const std::string& folderPath,
                      const FileWriter& writeFile = writeFileAtomically);

// One IEC file with every POU and the configuration (formatSingleFileIec),
// always in the IEC dialect whatever the model's setting, since CODESYS
// code names a GVL no IEC compiler knows.
Status exportStSingleFile(const Model& model, const std::string& filePath);

} // namespace core
