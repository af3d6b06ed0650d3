#!/usr/bin/env bash
# Retakes the pictures of the README and the user guide from the real
# program (tests/editor/screenshot.cpp), on the shipped examples, offscreen.
# Usage: docs/images/take-screenshots.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
shot="${1:-build}/tests/editor/ggstudio_screenshot"
export QT_QPA_PLATFORM=offscreen
images=docs/images
example=examples/drilling-cell.ggstudio.json

# The first start: the template and the start guide.
"$shot" "$images/main-window-template.png" 1366 768
# A transition being edited.
"$shot" "$images/main-window-transition.png" 1366 768 "$example" --select "A1->F2" --raise transitionDock
# The faulty example: the Problems dock and a step with problems.
"$shot" "$images/main-window-problem.png" 1920 1080 examples/drilling-cell-faulty.ggstudio.json \
    --select A7 --raise problemsDock
# The open-loop start scenario (the editor does not run the machine yet) replayed up to the first part being drilled.
"$shot" "$images/simulation.png" 1366 768 "$example" --simulate \
    --replay examples/drilling-cell-open-loop.scenario --replay-scans 1013 --raise simulationDock
# Scan 1,012 of it with F1's GRAFCET in front (F2's greyed in the tab beside it).
"$shot" "$images/simulation-grafcet.png" 1366 768 "$example" --grafcet F2 --grafcet F1 --simulate \
    --replay examples/drilling-cell-open-loop.scenario --replay-scans 1012 --raise simulationDock
# The nested GRAFCET of F1 in its tab, its transition T3 in the Nested Transition dock.
"$shot" "$images/grafcet-tab.png" 1366 768 "$example" --grafcet F1 --select F1/T3 --raise grafcetTransitionDock
# Verify and its findings.
"$shot" "$images/verification.png" 1366 768 "$example" --verify --raise problemsDock
