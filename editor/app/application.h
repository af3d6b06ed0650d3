#pragma once

#include <functional>

namespace editor {

class MainWindow;

// Places where a caller can look in on the startup, e.g. the startup probe
// of the benchmarks (tests/bench/startupprobe.cpp). Empty hooks are skipped.
struct StartupHooks {
    // The main window is built and about to be shown.
    std::function<void(MainWindow&)> windowCreated;
};

// GG Studio's whole run: the application's identity, translations, command
// line ([MODEL]), the main window, recovery of autosaved models, and the
// event loop. Returns the exit code. The GUI executable's main() only calls
// this, so the benchmarks measure the very startup users get.
int runApplication(int argc, char** argv, const StartupHooks& hooks = {});

} // namespace editor
