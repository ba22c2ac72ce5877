// The one branch driver's result in Python, OrbitBranch (py_orbit_branch.cpp),
// and its located points, SpecialOrbit, from which continue_doubled switches
// (py_special_orbit.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip::python {

// A located point of a branch (LP, PD, NS, GR, AD, CR, SL, CL) with what a
// switch or a new run from it needs: the system at the point and its run.
struct PySpecialOrbit {
  std::string label, lab, description, parameter, section;
  double p = 0, period = 0, run_from = 0, run_to = 0;
  py::array state, lo, hi, multipliers;
  int sticks = 0, exits = 0, crossings = 0, m = 1, turns = 0, contact = 0;
  bool stable = false;
  py::object system;    // a copy of the run's system, the parameter at p
  FlowPoint start;      // the row's section point, with its mode
  PoincareSection cut;  // the run's section
};

struct PyOrbitBranch {
  BranchStatus status = BranchStatus::kStartFailed;
  std::string message, parameter;
  std::vector<std::string> state_names;
  py::array p, state, period, sticks, exits, crossings, lo, hi, multipliers, stable, label;
  std::vector<py::tuple> special;  // (label, p, description)
  std::vector<PySpecialOrbit> special_points;
  int jumps = 0, evaluations = 0;
  double seconds = 0;
};

// The index of `name` in s, the run's system `system`; for Params and
// ForcedBeltParams a parameter of the law (or the forcing's) only.
int ParameterOf(const py::object& system, const System& s, const std::string& name);

// The driver's options for a run over `width` of the parameter: the forced
// oscillator's own tolerances for ForcedBeltParams (rtol = atol = 1e-12);
// max_step a share of width (default: the driver's ds_max).
OrbitBranchOptions BranchOptionsOf(const py::object& system, double width, double max_amplitude,
                                   std::optional<double> max_step, std::optional<double> rtol,
                                   std::optional<double> atol);

// b in Python: `system` is the run's (s the C++ one, j its parameter),
// [from, to] its range.
PyOrbitBranch ConvertBranch(const OrbitBranch& b, const System& s, int j, const py::object& system,
                            double from, double to);

// b's special points, each with `system` at its p (py_special_orbit.cpp).
std::vector<PySpecialOrbit> SpecialOrbits(const OrbitBranch& b, const System& s, int j,
                                          const py::object& system, double from, double to);

void BindSpecialOrbit(py::module_& m);  // SpecialOrbit and continue_doubled

}  // namespace stickslip::python
