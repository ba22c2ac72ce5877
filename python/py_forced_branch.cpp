// Branches of the forced oscillator in the Python module (issue 20, items 3
// and 6): continue_forced (as ss_continue --force --param) and
// continue_doubled (as ss_continue --switch at a PD label: AUTO-07p's
// ISW = -1), both without the GIL with Ctrl-C polled by the cancel hooks.
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "py_forced.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/branch.hpp"

namespace stickslip::python {

namespace {

// One located point of a branch (LP, PD, NS, GR, AD, CR, SL), with what
// a switch or a restart from it needs.
struct PyForcedSpecial {
  std::string label, description;
  ParameterAxis axis = Parameter::kOmega;
  ForcedParams params;  // every parameter at the point (axis = p)
  double p = 0, x0 = 0, xdot0 = 0;
  double run_from = 0, run_to = 0;  // the range of the run it was found in
  int m = 1, sticks = 0, crossings = 0;
  double x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;
  py::array multipliers;
  bool stable = false;
};

struct PyForcedBranch {
  ParameterAxis axis = Parameter::kOmega;
  BranchStatus status = BranchStatus::kStartFailed;
  std::string message;
  py::array p, x0, xdot0, m, sticks, crossings, x_min, x_max, xdot_min, xdot_max, stable,
      multipliers;
  std::vector<py::tuple> special;  // (label, p, x_max)
  std::vector<PyForcedSpecial> special_points;
  int jumps = 0, evaluations = 0;
  double seconds = 0;
};

OrbitBranchOptions Options(double width, double max_amplitude, std::optional<double> max_step,
                           std::optional<double> rtol, std::optional<double> atol) {
  OrbitBranchOptions o(FlowOf(rtol, atol));
  o.max_amplitude = max_amplitude;
  o.palc.ds_max = max_step.value_or(0.02) * width;  // as ss_continue's --max_step 0.02
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  return o;
}

PyForcedSpecial Special(const OrbitRow& s, int m, const ForcedParams& base, ParameterAxis axis,
                        double from, double to) {
  PyForcedSpecial q;
  q.label = Name(s.label), q.description = s.description, q.axis = axis;
  q.params = base;
  axis.Set(q.params, s.p);
  q.p = s.p, q.x0 = s.start.z[0], q.xdot0 = s.start.z[1], q.run_from = from, q.run_to = to;
  q.m = m, q.sticks = s.sticks, q.crossings = s.crossings, q.stable = s.stable;
  const Extrema e = RowExtrema(s);
  q.x_min = e.x_min, q.x_max = e.x_max, q.xdot_min = e.xdot_min, q.xdot_max = e.xdot_max;
  q.multipliers = ReadOnly(std::vector<std::complex<double>>{s.multipliers[0], s.multipliers[1]});
  return q;
}

PyForcedBranch MakeBranch(const OrbitBranch& r, const ForcedParams& base, ParameterAxis axis,
                          double from, double to) {
  PyForcedBranch out;
  out.axis = axis, out.status = r.status, out.message = r.message;
  out.jumps = r.jumps, out.evaluations = r.evaluations, out.seconds = r.seconds;
  std::vector<double> pp, x0, xd0, xmin, xmax, vmin, vmax;
  std::vector<int> mm, st, cr;
  std::vector<bool> stable;
  py::array_t<std::complex<double>> mult({static_cast<py::ssize_t>(r.rows.size()), py::ssize_t(2)});
  const int m = PeriodMultiple(r);
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const OrbitRow& w = r.rows[i];
    const Extrema e = RowExtrema(w);
    pp.push_back(w.p), x0.push_back(w.start.z[0]), xd0.push_back(w.start.z[1]), mm.push_back(m);
    st.push_back(w.sticks), cr.push_back(w.crossings), stable.push_back(w.stable);
    xmin.push_back(e.x_min), xmax.push_back(e.x_max);
    vmin.push_back(e.xdot_min), vmax.push_back(e.xdot_max);
    mult.mutable_at(i, 0) = w.multipliers[0], mult.mutable_at(i, 1) = w.multipliers[1];
  }
  mult.attr("setflags")(py::arg("write") = false);
  out.p = ReadOnly(pp), out.x0 = ReadOnly(x0), out.xdot0 = ReadOnly(xd0), out.m = ReadOnly(mm);
  out.sticks = ReadOnly(st), out.crossings = ReadOnly(cr), out.stable = ReadOnlyBool(stable);
  out.x_min = ReadOnly(xmin), out.x_max = ReadOnly(xmax);
  out.xdot_min = ReadOnly(vmin), out.xdot_max = ReadOnly(vmax), out.multipliers = mult;
  for (const OrbitRow& s : r.special) {
    out.special.push_back(py::make_tuple(Name(s.label), s.p, RowExtrema(s).x_max));
    out.special_points.push_back(Special(s, m, base, axis, from, to));
  }
  return out;
}

PyForcedBranch Continue(ForcedParams base, ParameterAxis axis, double from, double to,
                        std::optional<double> x_guess, std::optional<double> xdot_guess, int m,
                        double max_amplitude, std::optional<double> max_step,
                        std::optional<double> rtol, std::optional<double> atol) {
  OrbitBranchOptions o = Options(std::abs(to - from), max_amplitude, max_step, rtol, atol);
  Interrupt interrupt;
  o.palc.cancelled = [&] { return interrupt(); };
  OrbitBranch r;
  {
    py::gil_scoped_release nogil;
    r = ContinueForced(base, axis, from, to, x_guess.value_or(0), xdot_guess.value_or(base.base.v),
                       m, o);
  }
  interrupt.RaiseIfInterrupted();
  return MakeBranch(r, base, axis, from, to);
}

// The 2m branch from a PD point; [lo, hi] defaults to the range of the run the
// point came from (AUTO's RL0/RL1 kept, as ss_continue --switch).
PyForcedBranch Doubled(const PyForcedSpecial& pd, std::optional<double> lo,
                       std::optional<double> hi, double max_amplitude,
                       std::optional<double> max_step, std::optional<double> rtol,
                       std::optional<double> atol) {
  if (pd.label != "PD")
    throw InvalidArgument("point: label " + pd.label + " is not a period doubling (PD)");
  const double a = lo.value_or(std::min(pd.run_from, pd.run_to));
  const double b = hi.value_or(std::max(pd.run_from, pd.run_to));
  if (!(a < pd.p && pd.p < b))
    throw InvalidArgument("lo = " + Repr(a) + ", hi = " + Repr(b) + " must bracket the PD at " +
                          Repr(pd.p));
  OrbitBranchOptions o = Options(b - a, max_amplitude, max_step, rtol, atol);
  Interrupt interrupt;
  o.palc.cancelled = [&] { return interrupt(); };
  const ForcedParams at = pd.params;  // copies: read without the GIL
  const ParameterAxis axis = pd.axis;
  const double x0 = pd.x0, xdot0 = pd.xdot0;
  const int m = pd.m;
  OrbitBranch r;
  {
    py::gil_scoped_release nogil;
    r = ContinueDoubled(at, axis, x0, xdot0, a, b, m, o);
  }
  interrupt.RaiseIfInterrupted();
  return MakeBranch(r, at, axis, a, b);
}

template <typename C, typename... F>
void Fields(C& c, std::pair<const char*, F>... f) {
  (c.def_readonly(f.first, f.second), ...);
}

void BindClasses(py::module_& m) {
  using S = PyForcedSpecial;
  py::class_<S> s(m, "ForcedSpecialPoint",
                  "A located point of a forced branch (LP, PD, NS, GR, SW, AD, CR, SL): "
                  "continue_doubled() starts from a PD one.");
  s.def("__getitem__", &GetItem, py::arg("key")).def("__repr__", [](const S& q) {
    return "<ForcedSpecialPoint " + q.label + " at " + q.axis.name() + " = " + Repr(q.p) +
           ", m = " + std::to_string(q.m) + ">";
  });
  Fields(s, std::pair{"label", &S::label}, std::pair{"description", &S::description},
         std::pair{"axis", &S::axis}, std::pair{"params", &S::params}, std::pair{"p", &S::p},
         std::pair{"x0", &S::x0}, std::pair{"xdot0", &S::xdot0},
         std::pair{"run_from", &S::run_from}, std::pair{"run_to", &S::run_to},
         std::pair{"m", &S::m}, std::pair{"sticks", &S::sticks},
         std::pair{"crossings", &S::crossings}, std::pair{"x_min", &S::x_min},
         std::pair{"x_max", &S::x_max}, std::pair{"xdot_min", &S::xdot_min},
         std::pair{"xdot_max", &S::xdot_max}, std::pair{"multipliers", &S::multipliers},
         std::pair{"stable", &S::stable});
  using B = PyForcedBranch;
  py::class_<B> b(m, "ForcedBranch", "Result of continue_forced(): one array per row.");
  b.def("__getitem__", &GetItem, py::arg("key"));
  Fields(b, std::pair{"axis", &B::axis}, std::pair{"status", &B::status},
         std::pair{"message", &B::message}, std::pair{"p", &B::p}, std::pair{"x0", &B::x0},
         std::pair{"xdot0", &B::xdot0}, std::pair{"m", &B::m}, std::pair{"sticks", &B::sticks},
         std::pair{"crossings", &B::crossings}, std::pair{"x_min", &B::x_min},
         std::pair{"x_max", &B::x_max}, std::pair{"xdot_min", &B::xdot_min},
         std::pair{"xdot_max", &B::xdot_max}, std::pair{"stable", &B::stable},
         std::pair{"multipliers", &B::multipliers}, std::pair{"special", &B::special},
         std::pair{"special_points", &B::special_points}, std::pair{"jumps", &B::jumps},
         std::pair{"evaluations", &B::evaluations}, std::pair{"seconds", &B::seconds});
}

}  // namespace

void BindForcedBranch(py::module_& m) {
  BindClasses(m);
  const py::object none = py::none();
  m.def("continue_forced", &Continue, py::arg("params"), py::arg("axis"), py::arg("from_"),
        py::arg("to"), py::arg("x_guess") = none, py::arg("xdot_guess") = none, py::arg("m") = 1,
        py::arg("max_amplitude") = 1e3, py::arg("max_step") = none, py::arg("rtol") = none,
        py::arg("atol") = none,
        "The branch of m-periodic orbits through the one near (x_guess, xdot_guess) at "
        "axis = from_, continued to `to` (as ss_continue --force --param).");
  m.def("continue_doubled", &Doubled, py::arg("point"), py::arg("lo") = none, py::arg("hi") = none,
        py::arg("max_amplitude") = 1e3, py::arg("max_step") = none, py::arg("rtol") = none,
        py::arg("atol") = none,
        "The 2m-periodic branch born at a PD point (a ForcedSpecialPoint of a ForcedBranch), "
        "traced to lo or hi (default: the range of the run it came from), as ss_continue "
        "--switch.");
}

}  // namespace stickslip::python
