#include "core/simulation/simulationfault.h"

namespace core {

std::string toText(const SimulationFault& fault)
{
    return "scan " + std::to_string(fault.scan) + ": integer division by zero in " + fault.place + " (" + fault.division
        + " in '" + fault.text + "'): the PLC stops with a fault, and so does the simulation";
}

} // namespace core
