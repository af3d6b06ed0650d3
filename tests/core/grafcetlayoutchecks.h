#pragma once

// The invariants every computed GRAFCET layout keeps (docs/grafcet-layout.md):
// everything drawn once, in order; no box or label overlapping another; links
// orthogonal, joining their ends and crossing nothing; branch lines holding
// their branches in order; all inside the bounding rectangle. Shared by the
// layout's tests and the structured editing's, which prove with them that
// edited GRAFCETs still lay out cleanly.

#include "core/layout/grafcetlayout.h"
#include "core/model/grafcet.h"

#include <string>
#include <string_view>
#include <vector>

namespace grafcetlayoutchecks {

// 7 units per character (UTF-8 continuation bytes do not count).
double fixedWidth(std::string_view text);

// Every violated invariant, one line each (at most 20); empty when the layout is clean.
std::vector<std::string> violations(const core::Grafcet& grafcet, const core::GrafcetLayout& layout);

// The stable drawing (docs/grafcet-layout.md): one character more in a
// receptivity, or in a step's last action, moves no box, bar or line
// vertically, and sideways nothing at all while the text stays within its
// reserved room (core::kGrafcetLabelReserve). Every move found, one line
// each (at most 20); empty when the drawing is stable. Lays out the
// GRAFCET once per transition and step.
std::vector<std::string> labelWidthMoves(const core::Grafcet& grafcet);

} // namespace grafcetlayoutchecks
