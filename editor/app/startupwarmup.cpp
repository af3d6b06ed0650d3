#include "editor/app/startupwarmup.h"

#include <QDBusConnection>
#include <QFontDatabase>

#ifdef GGSTUDIO_HAVE_FONTCONFIG
#include <fontconfig/fontconfig.h>
#endif

#ifdef __linux__
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace editor {

namespace {

// Below the main thread and the display server: while QApplication is built
// the main thread keeps waiting for the X server's replies, and on two cores
// a warm-up at the same priority delays the server (measured: 1 to 1.5 ms
// later to the first frame). At nice 10 it still gets a core whenever one is
// idle, and all of one once the main thread waits for it.
void lowerThisThreadsPriority()
{
#ifdef __linux__
    // On Linux, PRIO_PROCESS with a thread id sets that thread's nice value.
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10);
#endif
}

} // namespace

StartupWarmUp::StartupWarmUp()
    : m_thread([this] { run(); })
{
}

StartupWarmUp::~StartupWarmUp()
{
    finish();
}

void StartupWarmUp::run()
{
    lowerThisThreadsPriority();
#ifdef GGSTUDIO_HAVE_FONTCONFIG
    // FcInit loads the default configuration and the font caches once per
    // process; Qt's font database then finds them loaded.
    FcInit();
#endif
    std::unique_lock lock(m_mutex);
    m_fontconfigLoaded = true;
    m_changed.notify_all();
    m_changed.wait(lock, [this] { return m_applicationReady || m_finishing; });
    if (!m_applicationReady)
        return;
    lock.unlock();
    QFontDatabase::families();
    QDBusConnection::sessionBus();
}

void StartupWarmUp::applicationReady()
{
    const std::lock_guard lock(m_mutex);
    m_applicationReady = true;
    m_changed.notify_all();
}

void StartupWarmUp::waitForFontconfig()
{
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_fontconfigLoaded; });
}

void StartupWarmUp::finish()
{
    {
        const std::lock_guard lock(m_mutex);
        m_finishing = true;
        m_changed.notify_all();
    }
    if (m_thread.joinable())
        m_thread.join();
}

} // namespace editor
