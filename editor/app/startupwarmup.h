#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

namespace editor {

// Start-up work that needs no widget, done on a second thread while the main
// thread connects to the display and builds the window:
//
//  1. fontconfig's configuration and font caches, from before QApplication.
//     On Linux Qt finds its fonts through fontconfig, and the first text a
//     window lays out makes fontconfig parse its XML configuration (dozens
//     of files under /etc/fonts): about 5 ms, just before the chart's first
//     label, on the start-up's critical path.
//  2. Once the application exists (applicationReady()): Qt's font database
//     (the font list it builds from fontconfig's) and the session bus
//     connection that Qt's accessibility bridge opens when the first dock
//     is built, which blocks the main thread until the bus answers (or, with
//     no session bus, until libdbus has failed to autolaunch one: 1.5 ms).
//     Both are shared by the whole process and guarded by Qt's own locks.
//
// waitForFontconfig() must come before anything lays out text: fontconfig
// does not make a second caller wait for its first initialisation but loads
// it all again. finish() must come before QApplication goes.
class StartupWarmUp {
public:
    StartupWarmUp();
    ~StartupWarmUp(); // finish()
    StartupWarmUp(const StartupWarmUp&) = delete;
    StartupWarmUp& operator=(const StartupWarmUp&) = delete;

    // QApplication exists and the start-up will reach the event loop (the
    // command line has been read: --help and --version exit before).
    void applicationReady();
    // Blocks until fontconfig is loaded.
    void waitForFontconfig();
    // Blocks until the thread is done; without applicationReady(), it skips
    // the second part.
    void finish();

private:
    void run();

    std::mutex m_mutex;
    std::condition_variable m_changed;
    bool m_fontconfigLoaded = false;
    bool m_applicationReady = false;
    bool m_finishing = false;
    std::thread m_thread;
};

} // namespace editor
