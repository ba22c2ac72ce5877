// Shared pieces of the forced oscillator's bindings (py_forced.cpp,
// py_forced_branch.cpp, py_chaos.cpp).
#pragma once

#include <optional>

#include "py_common.hpp"
#include "stickslip/forced/flow.hpp"

namespace stickslip::python {

// The forced flow's options: its own defaults (1e-12), rtol/atol over them;
// InvalidArgument naming the value if they are not valid.
FlowOptions FlowOf(std::optional<double> rtol, std::optional<double> atol);

void BindForcedBranch(py::module_& m);  // py_forced_branch.cpp
void BindChaos(py::module_& m);         // py_chaos.cpp

}  // namespace stickslip::python
