#include "filetestsupport.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

#ifndef _WIN32
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>
#endif

namespace filetests {

namespace {

void require(const core::Status& status)
{
    if (!status)
        throw std::logic_error("test model: " + status.message);
}

void addVariable(core::Model& model, std::string name, core::IecType type, std::string defaultValue)
{
    require(model.addVariable({std::move(name), type, std::move(defaultValue), {}}));
}

} // namespace

core::Model richGGModel()
{
    using core::IecType;
    core::Model model;
    addVariable(model, "Start", IecType::Bool, "");
    addVariable(model, "Stop", IecType::Bool, "TRUE");
    addVariable(model, "EmergencyStop", IecType::Bool, "FALSE");
    addVariable(model, "PieceCount", IecType::Int, "5");
    addVariable(model, "Speed", IecType::Real, "1.5e3");
    addVariable(model, "Level", IecType::Usint, "200");
    addVariable(model, "Total", IecType::Lint, "-9000000000");

    require(model.setInitialStep("A1"));
    require(model.setStepType("A1", core::StepType::Macro));
    require(model.setStepType("F1", core::StepType::Enclosing));
    require(model.setStepType("F4", core::StepType::Simple));
    require(model.setStepHidden("F6", true));
    require(model.setStepHidden("A7", true));

    require(model.setCondition("F->D1", "NOT EmergencyStop"));
    require(model.setCondition("A1->F4", "Start AND NOT Stop"));
    require(model.setTokens("A1->F4", {"Stop", "Start"}));
    require(model.setCondition("F1->A2", "NOT stop"));          // spelled unlike the declaration
    require(model.setTokens("F1->A2", {"Stop"}));
    require(model.setCondition("F1->F3", "Start AND PieceCount >= 3"));
    require(model.setTokens("F1->F3", {"Start"}));
    require(model.setCondition("F1->D2", "Speed > 2.5 OR Level = 7"));
    require(model.setCondition("D1->A5", "(Start)"));
    require(model.setCondition("A5->A7", "not yet valid ((")); // files keep what the user typed
    require(model.setNegated("F1->D1", false));
    require(model.setNegated("F5->F1", true));
    require(model.setOrder("F1->A2", 1));
    require(model.setOrder("A1->F5", 2));
    require(model.setOrder("F6->F1", 1));
    require(model.setTransitionHidden("A1->F2", true));
    require(model.setTransitionHidden("D3->D2", true));
    require(model.setTransitionHidden("F->D1", true));
    return model;
}

core::Model richNativeModel()
{
    core::Model model = richGGModel();
    require(model.setName("Bottle filler \"BF-2\""));
    require(model.setCycleTimeMs(35));
    model.setDialect(core::Dialect::Codesys);
    require(model.setStepComment("A1", "Waits for \"Start\".\nSecond line: 100 % ready, déjà vu, 始め"));
    require(model.setStepComment("D3", "tab\there, backslash \\ and <xml> & ST (* comment *)"));
    require(model.setVariableComment("Start", "Push button, normally open"));
    require(model.setVariableComment("Total", "{ \"not\": \"json\" }"));
    return model;
}

std::string readBinaryFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read " + path.string());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBinaryFile(const std::filesystem::path& path, const std::string& contents)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    if (!out)
        throw std::runtime_error("cannot write " + path.string());
}

#ifndef _WIN32
void makeFifo(const std::filesystem::path& path)
{
    if (::mkfifo(path.c_str(), 0644) != 0)
        throw std::runtime_error("cannot create the FIFO " + path.string());
}

void makeSocket(const std::filesystem::path& path)
{
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (path.string().size() >= sizeof address.sun_path)
        throw std::runtime_error("socket path too long: " + path.string());
    std::strcpy(address.sun_path, path.c_str());
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    const bool bound = fd >= 0 && ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
    if (fd >= 0)
        ::close(fd);
    if (!bound)
        throw std::runtime_error("cannot create the socket " + path.string());
}

std::filesystem::path harmlessCharacterDevice(const std::filesystem::path& folder)
{
    const std::filesystem::path node = folder / "null-device";
    if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0)
        return node;
    return "/dev/null";
}
#endif

ScratchFolder::ScratchFolder()
{
    std::string pattern = (std::filesystem::temp_directory_path() / "ggstudio-files-XXXXXX").string();
#ifdef _WIN32
    m_path = std::filesystem::path(pattern).replace_filename("ggstudio-files-" + std::to_string(std::rand()));
    std::filesystem::create_directories(m_path);
#else
    if (!::mkdtemp(pattern.data()))
        throw std::runtime_error("cannot create a scratch folder");
    m_path = pattern;
#endif
}

ScratchFolder::~ScratchFolder()
{
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
}

std::vector<std::string> ScratchFolder::entries() const
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(m_path))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace filetests
