#pragma once

// The Capper of spec packml.md §6.6 (tests/core/data/packml-capper.json),
// which the PackML chart and simulation tests of the editor run: Production
// with GRAFCETs in Resetting and Execute, Manual with the states that are
// never disabled.

#include "core/formats/modelfiles.h"
#include "core/model/model.h"

#include <QtGlobal>

namespace packmltest {

inline constexpr int kProduction = 1;
inline constexpr int kManual = 3;

inline core::Model capper()
{
    core::LoadedModel loaded = core::loadModelFile(GGSTUDIO_CORE_TEST_DATA_DIR "/packml-capper.json");
    if (!loaded.model)
        qFatal("cannot load the Capper");
    return *loaded.model;
}

} // namespace packmltest
