#pragma once

// How the GEMMA and PackML simulation sessions pace their scans against
// real time.

#include <QtGlobal>

namespace editor::simulationpacing {

// A tick that comes late (a busy machine, a modal dialog) does not try to
// catch up on more than this: simulated time then runs slower than real
// time instead of freezing the window.
constexpr double kMaxCatchUpSeconds = 0.1;

// A tick's scans stop after this much time, so that the event loop runs at
// least every kTickMs + kTickBudgetMs + one scan (a few milliseconds even
// for issue 32's 10,000-step unstable GRAFCET): what is left of the owed
// scans is dropped, simulated time then runs slower than real time.
constexpr qint64 kTickBudgetNs = 12'000'000;

} // namespace editor::simulationpacing
