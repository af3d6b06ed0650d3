#include "core/model/grafcetadjacency.h"

namespace core {

GrafcetAdjacency::GrafcetAdjacency(const Grafcet& grafcet)
{
    for (const GrafcetTransition& t : grafcet.transitions()) {
        for (int step : t.upstream)
            m_leaving[step].push_back(&t);
        for (int step : t.downstream)
            m_entering[step].push_back(&t);
    }
}

const std::vector<const GrafcetTransition*>& GrafcetAdjacency::leaving(int stepNumber) const
{
    return lookUp(m_leaving, stepNumber);
}

const std::vector<const GrafcetTransition*>& GrafcetAdjacency::entering(int stepNumber) const
{
    return lookUp(m_entering, stepNumber);
}

const std::vector<const GrafcetTransition*>& GrafcetAdjacency::lookUp(const Index& index, int stepNumber)
{
    static const std::vector<const GrafcetTransition*> none;
    const auto found = index.find(stepNumber);
    return found == index.end() ? none : found->second;
}

} // namespace core
