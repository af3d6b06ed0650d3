#pragma once

#include <thread>

namespace editor {

// Loads fontconfig's configuration and font caches on a second thread while
// the main thread connects to the display and builds the window.
//
// On Linux Qt finds its fonts through fontconfig, and the first text a
// window lays out makes fontconfig parse its XML configuration (dozens of
// files under /etc/fonts) and map its caches: about 5 ms here, spent on the
// main thread just before the chart's first label, in the middle of the
// start-up's critical path. Started before QApplication, the same work runs
// beside the platform's own start-up instead.
//
// wait() must come before anything lays out text: fontconfig does not make
// a second caller wait for its first initialisation but loads it all again.
// Without fontconfig (other platforms) this does nothing.
class FontconfigWarmUp {
public:
    FontconfigWarmUp();
    ~FontconfigWarmUp();
    FontconfigWarmUp(const FontconfigWarmUp&) = delete;
    FontconfigWarmUp& operator=(const FontconfigWarmUp&) = delete;

    // Blocks until fontconfig is loaded; later calls return at once.
    void wait();

private:
    std::thread m_thread;
};

} // namespace editor
