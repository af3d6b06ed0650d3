#include "readonlyfolder.h"

#ifndef _WIN32

#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace testsupport {

ReadOnlyFolder::ReadOnlyFolder(const std::filesystem::path& path)
    : m_path(path)
{
    if (::geteuid() == 0)
        m_immutable = std::system(("chattr +i '" + path.string() + "' 2>/dev/null").c_str()) == 0;
    else
        ::chmod(path.c_str(), 0555);
}

ReadOnlyFolder::~ReadOnlyFolder()
{
    if (m_immutable)
        (void)std::system(("chattr -i '" + m_path.string() + "'").c_str());
    ::chmod(m_path.c_str(), 0755);
}

bool ReadOnlyFolder::effective() const
{
    const std::filesystem::path probe = m_path / "probe";
    FILE* file = std::fopen(probe.c_str(), "w");
    if (!file)
        return true;
    std::fclose(file);
    std::remove(probe.c_str());
    return false;
}

} // namespace testsupport

#endif
