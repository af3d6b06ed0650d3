#include "samplemodels.h"

#include "core/codegen/stexport.h"
#include "core/codegen/stgenerator.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace test_stexport {

using namespace core;
namespace fs = std::filesystem;

namespace {

fs::path scratchFolder(const std::string& name)
{
    const fs::path folder = fs::temp_directory_path() / ("ggstudio-stexport-" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    return folder;
}

std::string readAll(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> namesOf(const std::vector<StFile>& files)
{
    std::vector<std::string> names;
    for (const StFile& file : files)
        names.push_back(file.name);
    return names;
}

} // namespace

TEST_CASE("The IEC folder export has one file per POU and the configuration", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    const std::vector<StFile> files = stFolderFiles(project);
    CHECK(namesOf(files) == std::vector<std::string>{"GEMMA.st", "F1_FB.st", "F2_FB.st", "F3_FB.st", "F4_FB.st",
                                                     "F5_FB.st", "D3_FB.st", "globals.st"});
    for (std::size_t i = 0; i < project.pous.size(); ++i)
        CHECK(files[i].text == formatPou(project.pous[i], Dialect::Iec));
    CHECK(files.back().text == formatConfiguration(project));
    CHECK(files.back().text.find("VAR_GLOBAL") != std::string::npos);
    CHECK(files.front().text.find("PROGRAM GEMMA") != std::string::npos);
}

TEST_CASE("The CODESYS folder export has the GVL file", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const PlcProject project = buildPlcProject(model, Dialect::Codesys);
    const std::vector<StFile> files = stFolderFiles(project);
    REQUIRE(!files.empty());
    CHECK(files.back().name == "GVL.st");
    CHECK(files.back().text == formatGlobals(project));
    CHECK(files.back().text.find("qualified_only") != std::string::npos);
    CHECK(files.front().text.find("GVL.") != std::string::npos);
}

TEST_CASE("Exporting a folder writes every file, creating the folder", "[plcopen]")
{
    const Model model = samples::caseStudyModel();
    const PlcProject project = buildPlcProject(model, Dialect::Iec);
    const fs::path folder = scratchFolder("nested") / "deeper" / "st";
    const Status status = exportStFolder(project, folder.string());
    REQUIRE(status.ok);
    for (const StFile& file : stFolderFiles(project))
        CHECK(readAll(folder / file.name) == file.text);

    SECTION("exporting again replaces the files and leaves others alone")
    {
        std::ofstream(folder / "notes.txt") << "mine";
        std::ofstream(folder / "GEMMA.st") << "stale";
        REQUIRE(exportStFolder(project, folder.string()).ok);
        CHECK(readAll(folder / "GEMMA.st") == stFolderFiles(project).front().text);
        CHECK(readAll(folder / "notes.txt") == "mine");
    }
}

TEST_CASE("Exporting a folder fails clearly", "[plcopen]")
{
    const PlcProject project = buildPlcProject(samples::caseStudyModel(), Dialect::Iec);
    SECTION("the path is a file")
    {
        const fs::path file = scratchFolder("plain-file");
        fs::create_directories(file.parent_path());
        std::ofstream(file) << "x";
        const Status status = exportStFolder(project, file.string());
        CHECK_FALSE(status.ok);
        CHECK(status.code == "stexport.folder");
        CHECK(status.message == "cannot write into \"" + file.string() + "\": it is a file, not a folder");
    }
    SECTION("the folder cannot be created")
    {
        const fs::path blocker = scratchFolder("blocker");
        fs::create_directories(blocker.parent_path());
        std::ofstream(blocker) << "x";
        const Status status = exportStFolder(project, (blocker / "sub").string());
        CHECK_FALSE(status.ok);
        CHECK(status.code == "stexport.folder");
        CHECK(status.message.find("cannot create the folder") != std::string::npos);
    }
    SECTION("no folder")
    {
        CHECK(exportStFolder(project, "").code == "stexport.folder");
    }
    SECTION("a POU name that is not an identifier writes nothing")
    {
        PlcProject bad = project;
        bad.pous.back().name = "../escape";
        const fs::path folder = scratchFolder("bad-name");
        const Status status = exportStFolder(bad, folder.string());
        CHECK(status.code == "stexport.file-name");
        CHECK_FALSE(fs::exists(folder));
    }
}

namespace {

// The files of a folder export, by name.
std::map<std::string, std::string> folderContents(const fs::path& folder)
{
    std::map<std::string, std::string> contents;
    for (const auto& entry : fs::directory_iterator(folder))
        contents[entry.path().filename().string()] = readAll(entry.path());
    return contents;
}

} // namespace

TEST_CASE("A folder export that fails half-way leaves the complete old set", "[plcopen]")
{
    const PlcProject before = buildPlcProject(samples::caseStudyModel(), Dialect::Iec);
    const fs::path folder = scratchFolder("half-way") / "st";
    REQUIRE(exportStFolder(before, folder.string()).ok);
    std::ofstream(folder / "notes.txt") << "mine";
    const std::map<std::string, std::string> old = folderContents(folder);

    PlcProject after = buildPlcProject(samples::caseStudyModel(), Dialect::Codesys);
    std::size_t writes = 0;
    const FileWriter diskFullAtTheThirdFile = [&](const std::string& path, std::string_view contents) {
        if (++writes == 3)
            return Status::failure("file.write", "cannot save \"" + path + "\": No space left on device");
        return writeFileAtomically(path, contents);
    };
    const Status status = exportStFolder(after, folder.string(), diskFullAtTheThirdFile);
    CHECK(status.code == "file.write");
    const std::string third = stFolderFiles(after)[2].name;
    CHECK(status.message == "cannot save \"" + (folder / third).string() + "\": No space left on device; nothing was changed");
    CHECK(writes == 3);
    CHECK(folderContents(folder) == old);
    // Nothing left beside the folder either.
    CHECK(std::distance(fs::directory_iterator(folder.parent_path()), fs::directory_iterator()) == 1);

    // The same export without the failure gives the complete new set.
    REQUIRE(exportStFolder(after, folder.string()).ok);
    for (const StFile& file : stFolderFiles(after))
        CHECK(readAll(folder / file.name) == file.text);
    CHECK(readAll(folder / "notes.txt") == "mine");
}

TEST_CASE("A folder export never replaces a FIFO in the folder", "[plcopen]")
{
    const PlcProject project = buildPlcProject(samples::caseStudyModel(), Dialect::Iec);
    const fs::path folder = scratchFolder("fifo-inside");
    fs::create_directories(folder);
    REQUIRE(::mkfifo((folder / "GEMMA.st").c_str(), 0644) == 0);
    const Status status = exportStFolder(project, folder.string());
    CHECK(status.code == "file.not-regular");
    CHECK(status.message == "cannot save \"" + (folder / "GEMMA.st").string()
        + "\": it is a named pipe (FIFO), not a regular file");
    CHECK(fs::is_fifo(fs::symlink_status(folder / "GEMMA.st")));
    CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 1);
}

TEST_CASE("The single-file export is IEC whatever the model's dialect", "[plcopen]")
{
    Model model = samples::caseStudyModel();
    model.setDialect(Dialect::Codesys);
    const fs::path file = scratchFolder("single") / "gemma.st";
    fs::create_directories(file.parent_path());
    REQUIRE(exportStSingleFile(model, file.string()).ok);
    const std::string text = readAll(file);
    CHECK(text == formatSingleFileIec(buildPlcProject(model, Dialect::Iec)));
    CHECK(text.find("CONFIGURATION") != std::string::npos);
    CHECK(text.find("GVL.") == std::string::npos);

    const Status missingFolder = exportStSingleFile(model, (file.parent_path() / "absent" / "x.st").string());
    CHECK_FALSE(missingFolder.ok);
    CHECK_FALSE(missingFolder.message.empty());
    CHECK(exportStSingleFile(model, "").code == "stexport.file-name");
}

} // namespace test_stexport
