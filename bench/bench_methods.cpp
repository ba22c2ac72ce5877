// The rows of ss_bench: ours (Continue), brute force and the regularised model.
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "brute_force.hpp"
#include "reference/reference_orbit.hpp"
#include "regularised.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"
namespace ssbench {

namespace ref = stickslip::reference;

namespace {

// Largest relative period error and absolute x_max error over kV; NaN
// entries (orbit not found) make the error NaN.
void Errors(const Reference& ref, const std::vector<double>& period,
            const std::vector<double>& x_max, Row* row) {
  double ep = 0, ex = 0;
  for (size_t i = 0; i < kV.size(); ++i) {
    const double a = std::abs(period[i] - ref.period[i]) / ref.period[i];
    const double b = std::abs(x_max[i] - ref.x_max[i]);
    ep = std::isnan(a) || std::isnan(ep) ? kNan : std::max(ep, a);
    ex = std::isnan(b) || std::isnan(ex) ? kNan : std::max(ex, b);
  }
  row->err_period = ep;
  row->err_xmax = ex;
}

// GR and HB as a user with orbits at kV only can place them: GR at the middle
// of the bracket where the cycle stops touching the belt; HB where amplitude^2,
// linear in v near a supercritical Hopf point, extrapolates to zero from the
// last two pure-slip speeds.
void SampledSpecialPoints(const Reference& ref, const std::vector<bool>& touches,
                          const std::vector<double>& amplitude, Row* row) {
  for (size_t i = 0; i + 1 < kV.size(); ++i)
    if (touches[i] && !touches[i + 1]) {
      row->err_gr = std::abs(0.5 * (kV[i] + kV[i + 1]) - ref.v_gr);
      row->n_gr = 1;
    }
  const size_t n = kV.size();
  if (!touches[n - 2] && !touches[n - 1] && !std::isnan(amplitude[n - 2] + amplitude[n - 1])) {
    const double a0 = amplitude[n - 2] * amplitude[n - 2], a1 = amplitude[n - 1] * amplitude[n - 1];
    if (a0 != a1) {
      row->err_hb = std::abs(kV[n - 2] + a0 * (kV[n - 1] - kV[n - 2]) / (a0 - a1) - ref.v_hb);
      row->n_hb = 1;
    }
  }
}

// ---------------------------------------------------------------- ours

// Pure-slip section amplitude at v, linear between the branch's neighbours.
double AmplitudeOnBranch(const ss::ContinuationResult& res, double v) {
  const ss::BranchPoint* lo = nullptr;
  const ss::BranchPoint* hi = nullptr;
  for (const auto& pt : res.points) {
    if (pt.kind != ss::PointKind::kPureSlip) continue;
    if (pt.p <= v && (!lo || pt.p > lo->p)) lo = &pt;
    if (pt.p >= v && (!hi || pt.p < hi->p)) hi = &pt;
  }
  if (!lo || !hi) return kNan;
  if (hi->p == lo->p) return lo->amplitude;
  return lo->amplitude + (hi->amplitude - lo->amplitude) * (v - lo->p) / (hi->p - lo->p);
}

ss::PointKind KindOnBranch(const ss::ContinuationResult& res, double v) {
  // The kind of the periodic point nearest to v.
  const ss::BranchPoint* best = nullptr;
  for (const auto& pt : res.points)
    if (pt.kind != ss::PointKind::kEquilibrium &&
        (!best || std::abs(pt.p - v) < std::abs(best->p - v)))
      best = &pt;
  return best ? best->kind : ss::PointKind::kEquilibrium;
}

// The 8 cycles of a simulation method at kV, timed (Repeat), into row: time,
// steps, points, and the errors of what the cycles measured. touches(c): the
// cycle reaches the belt speed (the GR bracket).
template <class Cycle, class One, class Touches>
std::vector<Cycle> TimeAndScore(const Reference& ref, One one, Touches touches, int min_reps,
                                int max_reps, Row* row) {
  std::vector<Cycle> cycles;
  auto run = [&] {
    cycles.clear();
    for (double v : kV) cycles.push_back(one(Seed(v)));
  };
  const Times t = Repeat(run, min_reps, max_reps, 2.0);
  row->t = t.Wall();
  row->cpu = t.Cpu();
  row->runs = t.runs();
  std::vector<double> period, x_max, amplitude;
  std::vector<bool> touch;
  for (const Cycle& c : cycles) {
    row->steps += c.steps;
    row->points += c.ok;
    period.push_back(c.ok ? c.period : kNan);
    x_max.push_back(c.ok ? c.x_max : kNan);
    amplitude.push_back(c.ok ? 0.5 * (c.x_max - c.x_min) : kNan);
    touch.push_back(c.ok && touches(c));
  }
  Errors(ref, period, x_max, row);
  SampledSpecialPoints(ref, touch, amplitude, row);
  return cycles;
}

}  // namespace

Row RunOurs(const Reference& ref, ss::Integrator integrator, ss::Method method, double rtol,
            int min_reps, int max_reps) {
  Row row;
  row.method = std::string("ours-") +
               (integrator == ss::Integrator::kTaylor ? ss::Name(integrator) : ss::Name(method));
  row.rtol = rtol;
  ss::ContinuationOptions co;  // param v, 0.05 -> 0.5, max_step 0.01
  co.orbit.flow.rtol = rtol;
  co.orbit.flow.atol = 1e-2 * rtol;
  co.orbit.flow.integrator = integrator;
  co.orbit.flow.method = method;
  const ss::Params base = Seed(0.25);

  ss::ContinuationResult res;
  const Times tb = Repeat([&] { res = ss::Continue(base, co); }, min_reps, max_reps, 1.5);
  row.t_branch = tb.Wall();
  row.runs = tb.runs();

  // Period and x_max at kV: the branch's own orbit code (OrbitFinder, the
  // same options) evaluated at exactly those v, since the adaptive steps do
  // not land on them. Kind and pure-slip start amplitude come from the branch.
  std::vector<double> period(kV.size(), kNan), x_max(kV.size(), kNan);
  long steps = 0;
  auto eval = [&] {
    ss::OrbitFinder finder(ss::Model(Seed(kV[0])), co.orbit);
    for (size_t i = 0; i < kV.size(); ++i) {
      finder.set_model(ss::Model(Seed(kV[i])));
      ss::OrbitResult o;
      if (KindOnBranch(res, kV[i]) == ss::PointKind::kStickSlip) {
        o = finder.StickSlip(/*first_return_only=*/true);
      } else {
        const double a = AmplitudeOnBranch(res, kV[i]);
        if (std::isnan(a) || a <= 0) continue;
        o = finder.PureSlip(a);
      }
      if (o.ok()) period[i] = o.orbit.period, x_max[i] = o.orbit.extrema.x_max;
    }
    steps = finder.flow().total_steps();
  };
  const Times te = Repeat(eval, min_reps, max_reps, 0.5);
  row.t_eval = te.Wall();
  row.t = row.t_branch + row.t_eval;
  row.cpu = tb.Cpu() + te.Cpu();
  row.cpu_branch = tb.Cpu();
  row.steps = steps;
  Errors(ref, period, x_max, &row);

  // Structure: special points, and the kinds along the periodic branch.
  for (const auto& sp : res.special) {
    if (sp.kind == ss::SpecialKind::kGrazing) {
      ++row.n_gr;
      row.err_gr = std::abs(sp.p - ref.v_gr);
    } else if (sp.kind == ss::SpecialKind::kHopf) {
      ++row.n_hb;
      row.err_hb = std::abs(sp.p - ref.v_hb);
    } else {
      ++row.n_lp;
    }
  }
  if (row.n_gr != 1) row.err_gr = kNan;
  if (row.n_hb != 1) row.err_hb = kNan;
  std::string kinds;
  ss::PointKind last = ss::PointKind::kEquilibrium;
  for (const auto& pt : res.points) {
    if (pt.kind == ss::PointKind::kEquilibrium) continue;
    ++row.points;
    if (pt.kind == last) continue;
    kinds += std::string(kinds.empty() ? "" : ">") +
             (pt.kind == ss::PointKind::kStickSlip ? "ss" : "ps");
    last = pt.kind;
  }
  row.kinds = kinds.empty() ? "-" : kinds;
  // The reference structure (GrazingSpeed, closed-form Hopf point, cubic law
  // supercritical): stick-slip up to one GR, pure slip down to one HB, no LP.
  const bool same =
      !res.partial() && row.n_gr == 1 && row.n_hb == 1 && row.n_lp == 0 && row.kinds == "ss>ps";
  row.same = same ? "yes" : "NO";
  if (res.partial()) row.note = std::string("continuation ") + ss::Name(res.status);
  return row;
}

// ---------------------------------------------------------------- brute force

Row RunBrute(const Reference& ref, double rtol, double t_cap, int min_reps, int max_reps) {
  Row row;
  row.method = "brute-adams";
  row.rtol = rtol;
  bench::BruteOptions bo;
  bo.flow.integrator = ss::Integrator::kCvode;
  bo.flow.rtol = rtol;
  bo.flow.atol = 1e-2 * rtol;
  bo.converge_tol = 10 * rtol;  // as tight as the integration allows
  bo.t_cap = t_cap;
  const auto cycles = TimeAndScore<bench::BruteCycle>(
      ref, [&](const ss::Params& p) { return bench::BruteForce(p, bo); },
      [](const bench::BruteCycle& c) { return c.t_stick > 0; }, min_reps, max_reps, &row);
  int capped = 0;
  for (const auto& c : cycles) capped += c.ok && !c.converged;
  char buf[96];
  std::snprintf(buf, sizeof buf, "t_end %.0f at v=%.2f%s", cycles.back().t_end, kV.back(),
                capped ? " (t_cap hit)" : "");
  row.note = buf;
  return row;
}

// ---------------------------------------------------------------- regularised

// Integration tolerance for a given eps, from a pilot sweep (rtol 1e-4 ..
// 1e-10 at each eps): the loosest decade at which both max errors are within
// ~10% of their rtol = 1e-10 values. The regularisation error is ~10 eps in
// period (v = 0.05 dominates); looser rtol at eps <= 1e-5 fails or is worse.
double RegularisedRtol(double eps) { return std::clamp(1e-2 * eps, 1e-10, 1e-6); }

Row RunRegularised(const Reference& ref, double eps, double rtol, int min_reps, int max_reps) {
  Row row;
  row.method = "regularised-bdf";
  row.eps = eps;
  row.rtol = rtol;
  bench::SmoothOptions so;
  so.eps = eps;
  so.rtol = rtol;
  so.atol = 1e-2 * rtol;
  const auto cycles = TimeAndScore<bench::SmoothCycle>(
      ref, [&](const ss::Params& p) { return bench::RegularisedCycle(p, so); },
      [](const bench::SmoothCycle& c) { return c.touches; }, min_reps, max_reps, &row);
  std::string failed;
  for (size_t i = 0; i < cycles.size(); ++i)
    if (!cycles[i].ok)
      failed += (failed.empty() ? "no cycle at v=" : ",") + std::to_string(kV[i]).substr(0, 4);
  row.note = failed;
  return row;
}

}  // namespace ssbench
