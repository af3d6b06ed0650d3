#pragma once

// The transitions leaving and entering each step of a GRAFCET, built once.
// Grafcet::transitionsFrom scans every transition; a check or a walk that
// asks it for every step is quadratic, and a 10,000-step GRAFCET then takes
// minutes instead of milliseconds. Valid while the GRAFCET is unchanged.

#include "core/model/grafcet.h"

#include <unordered_map>
#include <vector>

namespace core {

class GrafcetAdjacency {
public:
    explicit GrafcetAdjacency(const Grafcet& grafcet);

    // In the order of the GRAFCET's transitions, as Grafcet::transitionsFrom.
    const std::vector<const GrafcetTransition*>& leaving(int stepNumber) const;
    const std::vector<const GrafcetTransition*>& entering(int stepNumber) const;

private:
    using Index = std::unordered_map<int, std::vector<const GrafcetTransition*>>;
    static const std::vector<const GrafcetTransition*>& lookUp(const Index& index, int stepNumber);

    Index m_leaving;
    Index m_entering;
};

} // namespace core
