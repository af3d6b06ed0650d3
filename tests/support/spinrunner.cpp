#include "spinrunner.h"

#include "core/verification/promela.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <stdlib.h> // mkdtemp

namespace spin {

namespace fs = std::filesystem;

namespace {

bool succeeds(const std::string& command)
{
    return std::system((command + " > /dev/null 2>&1").c_str()) == 0;
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void runShell(const std::string& command)
{
    if (std::system(command.c_str()) == -1)
        throw std::runtime_error("cannot start the shell for: " + command);
}

} // namespace

bool available()
{
    return succeeds("spin -V") && succeeds("gcc --version");
}

CompiledPan::CompiledPan(const std::string& promelaText, const std::string& name, const std::string& compileFlags,
                         const std::string& generate)
{
    if (!available())
        throw std::runtime_error("spin or gcc is missing (Debian packages spin and gcc)");
    std::string pattern = (fs::temp_directory_path() / ("ggstudio-spin-" + name + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr)
        throw std::runtime_error("cannot create a temporary folder " + pattern);
    m_folder = pattern;
    {
        std::ofstream out(m_folder / "model.pml", std::ios::binary);
        out << promelaText;
    }
    const std::string command = "cd '" + m_folder.string() + "' && timeout 120 " + generate
        + " model.pml > spin.log 2>&1 && timeout 900 gcc " + compileFlags + " -o pan pan.c > cc.log 2>&1";
    if (std::system(command.c_str()) != 0) {
        const std::string message = "spin: " + readText(m_folder / "spin.log") + "\ncc: " + readText(m_folder / "cc.log");
        std::error_code ignored;
        fs::remove_all(m_folder, ignored);
        throw std::runtime_error(message);
    }
}

CompiledPan::~CompiledPan()
{
    std::error_code ignored;
    fs::remove_all(m_folder, ignored);
}

std::string CompiledPan::run(const std::string& environment, const std::string& arguments) const
{
    runShell("cd '" + m_folder.string() + "' && " + environment + " timeout 300 ./pan " + arguments + " > pan.txt 2>&1");
    return readText(m_folder / "pan.txt");
}

std::vector<std::string> CompiledPan::runFrom(const std::vector<std::string>& starts, int until, long long depth) const
{
    {
        std::ofstream out(m_folder / "starts.txt", std::ios::binary);
        for (const std::string& start : starts)
            out << start << "\n";
    }
    const std::string loop = "i=0; while IFS= read -r start; do i=$((i+1)); " + std::string(core::kSpinStartVariable)
        + "=\"$start\" " + core::kSpinUntilVariable + "=" + std::to_string(until) + " ./pan -m" + std::to_string(depth)
        + " -w14 > from-$i.txt 2>&1; done < starts.txt";
    runShell("cd '" + m_folder.string() + "' && timeout 300 sh -c '" + loop + "'");
    std::vector<std::string> outputs;
    for (std::size_t i = 1; i <= starts.size(); ++i)
        outputs.push_back(readText(m_folder / ("from-" + std::to_string(i) + ".txt")));
    return outputs;
}

} // namespace spin
