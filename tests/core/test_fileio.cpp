#include "filetestsupport.h"
#include "readonlyfolder.h"

#include "core/formats/fileio.h"
#include "core/formats/modelfiles.h"
#include "core/formats/nativeformat.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace test_fileio {

using namespace core;
using filetests::ScratchFolder;
#ifndef _WIN32
using testsupport::ReadOnlyFolder;
#endif
namespace fs = std::filesystem;

TEST_CASE("Valid UTF-8 passes the check", "[files]")
{
    CHECK_FALSE(findInvalidUtf8(""));
    CHECK_FALSE(findInvalidUtf8("plain ASCII\n"));
    CHECK_FALSE(findInvalidUtf8("déjà vu \xE2\x82\xAC \xF0\x9F\x98\x80 \xF4\x8F\xBF\xBF"));
}

TEST_CASE("Invalid UTF-8 is found at its first bad byte with line and column", "[files]")
{
    struct Case {
        std::string text;
        std::size_t offset;
        std::size_t line;
        std::size_t column;
    };
    const Case cases[] = {
        {"ab\xFF", 2, 1, 3},
        {"ab\ncd\x80", 5, 2, 3},                        // lone continuation byte
        {"x\n\xC3\xA9t\xC3\xA9 \xC0\xAF", 8, 2, 5},     // overlong '/': columns count characters
        {"\xED\xA0\x80", 0, 1, 1},                      // UTF-16 surrogate
        {"ok \xF4\x90\x80\x80", 3, 1, 4},               // above U+10FFFF
        {"end \xE2\x82", 4, 1, 5},                      // cut short by the end of the text
        {"\xE2\x28\xA1", 0, 1, 1},                      // bad second byte
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const auto problem = findInvalidUtf8(c.text);
        REQUIRE(problem);
        CHECK(problem->offset == c.offset);
        CHECK(problem->position.line == c.line);
        CHECK(problem->position.column == c.column);
    }
}

TEST_CASE("Byte offsets become lines and character columns", "[files]")
{
    const std::string text = "ab\n\xC3\xA9x\n";
    CHECK(describePosition(textPosition(text, 0)) == "line 1, column 1");
    CHECK(describePosition(textPosition(text, 3)) == "line 2, column 1");
    CHECK(describePosition(textPosition(text, 5)) == "line 2, column 2");
    CHECK(describePosition(textPosition(text, 6)) == "line 2, column 3");
    CHECK(describePosition(textPosition(text, 99)) == "line 3, column 1");
    CHECK(describePosition(textPosition("\xEF\xBB\xBF{x", 4)) == "line 1, column 2"); // the BOM takes no column
}

TEST_CASE("A limited read returns the whole file", "[files]")
{
    ScratchFolder folder;
    const std::string contents = std::string("binary\0data\n", 12) + std::string(200000, 'x');
    filetests::writeBinaryFile(folder.file("a.json"), contents);
    std::string read;
    REQUIRE(readFileLimited(folder.file("a.json").string(), kMaxModelFileBytes, read));
    CHECK(read == contents);
}

TEST_CASE("A limited read refuses missing files, folders and files over the limit", "[files]")
{
    ScratchFolder folder;
    std::string read = "untouched";

    Status status = readFileLimited(folder.file("missing.json").string(), 100, read);
    CHECK(status.code == "file.open");
    CHECK_THAT(status.message, Catch::Contains("cannot open"));

    status = readFileLimited(folder.path().string(), 100, read);
    CHECK(status.code == "file.not-regular");

    filetests::writeBinaryFile(folder.file("big.json"), std::string(101, ' '));
    status = readFileLimited(folder.file("big.json").string(), 100, read);
    CHECK(status.code == "file.too-large");
    CHECK(status.message == "the file is 101 bytes; files larger than 100 bytes are not read");
    CHECK(read == "untouched");
}

TEST_CASE("A model file over 64 MiB is refused before it is read", "[files]")
{
    ScratchFolder folder;
    const fs::path huge = folder.file("huge.json");
    filetests::writeBinaryFile(huge, "{");
    fs::resize_file(huge, 80ull * 1024 * 1024); // sparse: costs no disk space
    REQUIRE(fs::file_size(huge) > kMaxModelFileBytes);

    const LoadedModel loaded = loadModelFile(huge.string());

    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error.file == huge.string());
    CHECK(loaded.error.message
        == "the file is 83886080 bytes (80.0 MiB); files larger than 67108864 bytes (64.0 MiB) are not read");
}

TEST_CASE("An atomic write creates and replaces files and leaves no temporary file", "[files]")
{
    ScratchFolder folder;
    const std::string path = folder.file("model.json").string();
    REQUIRE(writeFileAtomically(path, "first"));
    CHECK(filetests::readBinaryFile(path) == "first");
    REQUIRE(writeFileAtomically(path, "second, longer"));
    CHECK(filetests::readBinaryFile(path) == "second, longer");
    REQUIRE(writeFileAtomically(path, ""));
    CHECK(filetests::readBinaryFile(path).empty());
    CHECK(folder.entries() == std::vector<std::string>{"model.json"});
}

TEST_CASE("An atomic write onto a folder fails and changes nothing", "[files]")
{
    ScratchFolder folder;
    fs::create_directory(folder.file("model.json"));
    filetests::writeBinaryFile(folder.file("model.json") / "inside.txt", "keep");

    const Status status = writeFileAtomically(folder.file("model.json").string(), "data");
    CHECK_FALSE(status);
    CHECK(status.code == "file.not-regular");
    CHECK(status.message == "cannot save \"" + folder.file("model.json").string() + "\": it is a folder, not a file");
    CHECK(fs::is_directory(folder.file("model.json")));
    CHECK(filetests::readBinaryFile(folder.file("model.json") / "inside.txt") == "keep");
    CHECK(folder.entries() == std::vector<std::string>{"model.json"});
}

TEST_CASE("An atomic write into a missing folder fails", "[files]")
{
    ScratchFolder folder;
    const Status status = writeFileAtomically(folder.file("no/such/folder/model.json").string(), "data");
    CHECK_FALSE(status);
    CHECK_THAT(status.message, Catch::Contains("cannot create a temporary file"));
    CHECK(folder.entries().empty());
}

#ifndef _WIN32
TEST_CASE("An atomic write in a read-only folder keeps the old file", "[files]")
{
    ScratchFolder folder;
    const fs::path target = folder.file("model.json");
    filetests::writeBinaryFile(target, "old contents");
    {
        ReadOnlyFolder readOnly(folder.path());
        if (!readOnly.effective()) {
            WARN("cannot make a read-only folder here (no chattr for root?)");
            return;
        }
        const Status status = writeFileAtomically(target.string(), "new contents");
        CHECK_FALSE(status);
        CHECK(status.code == "file.write");
        CHECK_THAT(status.message, Catch::Contains("model.json") && Catch::Contains("temporary file"));
    }
    CHECK(filetests::readBinaryFile(target) == "old contents");
    CHECK(folder.entries() == std::vector<std::string>{"model.json"});
}

TEST_CASE("An atomic write keeps the permissions of the replaced file", "[files]")
{
    ScratchFolder folder;
    const fs::path target = folder.file("model.json");
    filetests::writeBinaryFile(target, "old");
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    REQUIRE(writeFileAtomically(target.string(), "new"));
    CHECK(filetests::readBinaryFile(target) == "new");
    CHECK((fs::status(target).permissions() & fs::perms::all)
        == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
}

TEST_CASE("An atomic write through a symbolic link replaces the file it points to", "[files]")
{
    ScratchFolder folder;
    filetests::writeBinaryFile(folder.file("real.json"), "old");
    fs::create_symlink("real.json", folder.file("link.json"));
    REQUIRE(writeFileAtomically(folder.file("link.json").string(), "new"));
    CHECK(fs::is_symlink(fs::symlink_status(folder.file("link.json"))));
    CHECK(filetests::readBinaryFile(folder.file("real.json")) == "new");
    CHECK(folder.entries() == std::vector<std::string>{"link.json", "real.json"});
}

TEST_CASE("An atomic write refuses a FIFO, a socket and a device and leaves them as they were", "[files]")
{
    ScratchFolder folder;
    const fs::path fifo = folder.file("pipe.json");
    filetests::makeFifo(fifo);
    const fs::path socket = folder.file("socket.json");
    filetests::makeSocket(socket);
    const fs::path device = filetests::harmlessCharacterDevice(folder.path());
    const auto refusal = [](const fs::path& target) {
        const Status status = writeFileAtomically(target.string(), "data");
        CHECK_FALSE(status);
        CHECK(status.code == "file.not-regular");
        return status.message;
    };

    CHECK(refusal(fifo) == "cannot save \"" + fifo.string() + "\": it is a named pipe (FIFO), not a regular file");
    CHECK(fs::is_fifo(fs::symlink_status(fifo)));
    CHECK(refusal(socket) == "cannot save \"" + socket.string() + "\": it is a socket, not a regular file");
    CHECK(fs::is_socket(fs::symlink_status(socket)));
    CHECK(refusal(device) == "cannot save \"" + device.string() + "\": it is a character device, not a regular file");
    CHECK(fs::is_character_file(fs::symlink_status(device)));
    // No temporary file left behind beside any of them.
    for (const std::string& name : folder.entries())
        CHECK(name.find(".tmp-") == std::string::npos);
}

TEST_CASE("An atomic write through a link to a device or a FIFO is refused; the link and its target stay", "[files]")
{
    ScratchFolder folder;
    const fs::path device = filetests::harmlessCharacterDevice(folder.path());
    fs::create_symlink(device, folder.file("to-device.json"));
    filetests::makeFifo(folder.file("pipe"));
    fs::create_symlink("pipe", folder.file("to-fifo.json"));

    Status status = writeFileAtomically(folder.file("to-device.json").string(), "data");
    CHECK(status.code == "file.not-regular");
    CHECK(status.message == "cannot save \"" + folder.file("to-device.json").string() + "\": it links to \""
        + fs::canonical(device).string() + "\", which is a character device, not a regular file");
    CHECK(fs::is_character_file(fs::status(device)));
    CHECK(fs::is_symlink(fs::symlink_status(folder.file("to-device.json"))));

    status = writeFileAtomically(folder.file("to-fifo.json").string(), "data");
    CHECK(status.code == "file.not-regular");
    CHECK_THAT(status.message, Catch::Contains("which is a named pipe (FIFO)"));
    CHECK(fs::is_fifo(fs::symlink_status(folder.file("pipe"))));
    CHECK(fs::is_symlink(fs::symlink_status(folder.file("to-fifo.json"))));
}

TEST_CASE("saveModelFile refuses a FIFO: the model never replaces it", "[files]")
{
    ScratchFolder folder;
    filetests::makeFifo(folder.file("model.json"));
    const Status status = saveModelFile(filetests::richNativeModel(), folder.file("model.json").string(),
                                        ModelFormat::Native);
    CHECK(status.code == "file.not-regular");
    CHECK(fs::is_fifo(fs::symlink_status(folder.file("model.json"))));
    CHECK(folder.entries() == std::vector<std::string>{"model.json"});
}

TEST_CASE("A folder write creates the folder, replaces its files all at once and keeps the user's", "[files]")
{
    ScratchFolder scratch;
    const fs::path folder = scratch.file("out") / "st";
    REQUIRE(writeFolderAtomically(folder.string(), {{"A.st", "a1"}, {"B.st", "b1"}}));
    CHECK(filetests::readBinaryFile(folder / "A.st") == "a1");
    CHECK(filetests::readBinaryFile(folder / "B.st") == "b1");

    filetests::writeBinaryFile(folder / "notes.txt", "mine");
    fs::create_directory(folder / "sub");
    filetests::writeBinaryFile(folder / "sub" / "deep.txt", "deep");
    fs::create_symlink("notes.txt", folder / "notes-link");
    fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
    REQUIRE(writeFolderAtomically(folder.string(), {{"A.st", "a2"}, {"C.st", "c2"}}));

    CHECK(filetests::readBinaryFile(folder / "A.st") == "a2");
    CHECK(filetests::readBinaryFile(folder / "C.st") == "c2");
    CHECK(filetests::readBinaryFile(folder / "B.st") == "b1"); // not in the new set: the user's now
    CHECK(filetests::readBinaryFile(folder / "notes.txt") == "mine");
    CHECK(filetests::readBinaryFile(folder / "sub" / "deep.txt") == "deep");
    CHECK(fs::read_symlink(folder / "notes-link") == "notes.txt");
    CHECK((fs::status(folder).permissions() & fs::perms::all)
        == (fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec));
    // No staging or old folder left beside it.
    CHECK(std::vector<std::string>{fs::directory_iterator(scratch.file("out"))->path().filename().string()}
        == std::vector<std::string>{"st"});
}

TEST_CASE("A folder write that fails half-way leaves the old files, all of them", "[files]")
{
    ScratchFolder scratch;
    const fs::path folder = scratch.file("st");
    REQUIRE(writeFolderAtomically(folder.string(), {{"1.st", "old 1"}, {"2.st", "old 2"}, {"3.st", "old 3"}}));
    int writes = 0;
    const FileWriter fullDiskAtTheThirdFile = [&](const std::string& path, std::string_view contents) {
        if (++writes == 3)
            return Status::failure("file.write", "cannot save \"" + path + "\": No space left on device");
        return writeFileAtomically(path, contents);
    };

    const Status status = writeFolderAtomically(folder.string(), {{"1.st", "new 1"}, {"2.st", "new 2"}, {"3.st", "new 3"}},
                                                fullDiskAtTheThirdFile);
    CHECK(status.code == "file.write");
    CHECK(status.message == "cannot save \"" + (folder / "3.st").string()
        + "\": No space left on device; nothing was changed");
    CHECK(filetests::readBinaryFile(folder / "1.st") == "old 1");
    CHECK(filetests::readBinaryFile(folder / "2.st") == "old 2");
    CHECK(filetests::readBinaryFile(folder / "3.st") == "old 3");
    CHECK(scratch.entries() == std::vector<std::string>{"st"});
}

TEST_CASE("A folder write refuses what is not a folder, and special files inside it", "[files]")
{
    ScratchFolder scratch;
    filetests::makeFifo(scratch.file("pipe"));
    Status status = writeFolderAtomically(scratch.file("pipe").string(), {{"A.st", "a"}});
    CHECK(status.code == "file.not-folder");
    CHECK(status.message == "cannot write into \"" + scratch.file("pipe").string()
        + "\": it is a named pipe (FIFO), not a folder");
    CHECK(fs::is_fifo(fs::symlink_status(scratch.file("pipe"))));

    const fs::path folder = scratch.file("st");
    fs::create_directory(folder);
    filetests::writeBinaryFile(folder / "A.st", "old");
    filetests::makeFifo(folder / "B.st");
    status = writeFolderAtomically(folder.string(), {{"A.st", "new"}, {"B.st", "new"}});
    CHECK(status.code == "file.not-regular");
    CHECK(status.message == "cannot save \"" + (folder / "B.st").string() + "\": it is a named pipe (FIFO), not a regular file");
    CHECK(fs::is_fifo(fs::symlink_status(folder / "B.st")));
    CHECK(filetests::readBinaryFile(folder / "A.st") == "old");
    CHECK(scratch.entries() == std::vector<std::string>{"pipe", "st"});

    // Writing through a link would change a file outside before the swap.
    fs::remove(folder / "B.st");
    fs::create_symlink("A.st", folder / "B.st");
    status = writeFolderAtomically(folder.string(), {{"B.st", "new"}});
    CHECK(status.code == "file.not-regular");
    CHECK_THAT(status.message, Catch::Contains("it is a symbolic link"));
    CHECK(filetests::readBinaryFile(folder / "A.st") == "old");
}

TEST_CASE("A folder write through a link to a folder replaces the folder and keeps the link", "[files]")
{
    ScratchFolder scratch;
    fs::create_directory(scratch.file("real"));
    filetests::writeBinaryFile(scratch.file("real") / "A.st", "old");
    fs::create_directory_symlink("real", scratch.file("link"));
    REQUIRE(writeFolderAtomically(scratch.file("link").string() + "/", {{"A.st", "new"}}));
    CHECK(fs::is_symlink(fs::symlink_status(scratch.file("link"))));
    CHECK(filetests::readBinaryFile(scratch.file("real") / "A.st") == "new");
    CHECK(scratch.entries() == std::vector<std::string>{"link", "real"});
}
#endif

TEST_CASE("LoadError reads FILE: LOCATION: MESSAGE", "[files]")
{
    CHECK(LoadError{"m.json", "/steps/F1/hidden", "expected true or false, found \"yes\""}.toString()
        == "m.json: /steps/F1/hidden: expected true or false, found \"yes\"");
    CHECK(LoadError{"m.json", "", "the file is empty"}.toString() == "m.json: the file is empty");
    CHECK(LoadError{"", "line 1, column 2", "bad"}.toString() == "<input>: line 1, column 2: bad");
}

TEST_CASE("Model files are recognised by their content", "[files]")
{
    const std::string native = saveNativeJson(filetests::richNativeModel());
    LoadedModel loaded = loadModelText(native, "a.txt");
    REQUIRE(loaded.ok());
    CHECK(loaded.format == ModelFormat::Native);
    CHECK(loaded.model->sameContent(filetests::richNativeModel()));

    loaded = loadModelText("\xEF\xBB\xBF \n" + native, "bom.json");
    REQUIRE(loaded.ok());
    CHECK(loaded.format == ModelFormat::Native);

    const std::string reference = filetests::readBinaryFile(fs::path(GGSTUDIO_REFERENCE_DIR) / "gg-generator/template.json");
    loaded = loadModelText(reference, "gg.json");
    REQUIRE(loaded.ok());
    CHECK(loaded.format == ModelFormat::GGGenerator);

    loaded = loadModelText("  <?xml version=\"1.0\"?><nothing/>", "p.xml");
    CHECK_FALSE(loaded.ok());
    CHECK(loaded.format == ModelFormat::PlcOpen);

    loaded = loadModelText(" \n\t", "empty.json");
    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error.toString() == "empty.json: the file is empty");

    loaded = loadModelText("{\"name\": \"x\"}", "other.json");
    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error.location == "/format");

    loaded = loadModelText("hello", "hello.txt");
    REQUIRE_FALSE(loaded.ok());
    CHECK_THAT(loaded.error.message, Catch::StartsWith("not a model file"));
}

TEST_CASE("A NUL byte in a model file is an error at its place, whatever the format", "[files]")
{
    const std::string nul(1, '\0');
    // A GG-Generator file whose real content follows a NUL: the part before
    // it used to load alone, as a template.
    const std::string reference = filetests::readBinaryFile(fs::path(GGSTUDIO_REFERENCE_DIR) / "gg-generator/template.json");
    LoadedModel loaded = loadModelText("{\"nodes\": [], \"connections\": []}\n" + nul + reference, "gg.json");
    CHECK(loaded.format == ModelFormat::GGGenerator);
    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error.toString()
          == "gg.json: line 2, column 1: a NUL byte outside any string: JSON text cannot contain one");

    loaded = loadModelText(saveNativeJson(filetests::richNativeModel()) + nul + "garbage", "native.json");
    CHECK(loaded.format == ModelFormat::Native);
    REQUIRE_FALSE(loaded.ok());
    CHECK_THAT(loaded.error.message, Catch::StartsWith("a NUL byte"));

    // Not "the file is empty": it is not.
    loaded = loadModelText(" " + nul + "{}", "binary.json");
    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error.location == "line 1, column 2");
    CHECK_THAT(loaded.error.message, Catch::StartsWith("a NUL byte"));
}

TEST_CASE("saveModelFile writes native and GG-Generator files that load back", "[files]")
{
    ScratchFolder folder;
    const Model model = filetests::richGGModel();

    const std::string nativePath = folder.file("model.ggstudio.json").string();
    REQUIRE(saveModelFile(model, nativePath, ModelFormat::Native));
    LoadedModel loaded = loadModelFile(nativePath);
    REQUIRE(loaded.ok());
    CHECK(loaded.format == ModelFormat::Native);
    CHECK(loaded.model->sameContent(model));

    const std::string ggPath = folder.file("model.gg.json").string();
    REQUIRE(saveModelFile(model, ggPath, ModelFormat::GGGenerator));
    loaded = loadModelFile(ggPath);
    REQUIRE(loaded.ok());
    CHECK(loaded.format == ModelFormat::GGGenerator);
    CHECK(loaded.model->sameContent(model));

    CHECK_FALSE(saveModelFile(model, folder.file("model.xml").string(), ModelFormat::PlcOpen));
    CHECK(folder.entries() == std::vector<std::string>{"model.gg.json", "model.ggstudio.json"});
}

} // namespace test_fileio
