#include "stickslip/orbits/orbit.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "numerics/roots.hpp"
#include "numerics/stall.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string OrbitOptions::ValidationError() const {
  std::string err = flow.ValidationError();
  if (!err.empty()) return err;
  std::ostringstream os;
  if (!(max_return_time > 0) || !std::isfinite(max_return_time))
    os << "max_return_time = " << max_return_time << " must be a finite number > 0";
  else if (max_newton < 1)
    os << "max_newton = " << max_newton << " must be >= 1";
  else if (!(newton_tol > 0 && newton_tol < 1))
    os << "newton_tol = " << newton_tol << " must be in (0, 1)";
  return os.str();
}

namespace {
const OrbitOptions& Checked(const OrbitOptions& o) {
  const std::string err = o.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  return o;
}

OrbitStatus FromFlowStatus(FlowStatus s) {
  switch (s) {
    case FlowStatus::kIntegratorFailed:
    case FlowStatus::kTooManySwitches:
      return OrbitStatus::kIntegratorFailed;
    case FlowStatus::kCancelled:
      return OrbitStatus::kCancelled;
    case FlowStatus::kTimeLimit:
      return OrbitStatus::kNoReturn;
    case FlowStatus::kStick:
      return OrbitStatus::kSticks;
    default:
      return OrbitStatus::kOk;
  }
}

void CopyExtremes(Orbit& o, const FlowResult& r) {
  o.extrema = r.extrema;
  o.modes = r.modes;
  o.crossings = r.crossings;
}
}  // namespace

OrbitFinder::OrbitFinder(const FrictionSystem& system, const OrbitOptions& options)
    : options_(Checked(options)), flow_(system, options.flow) {}

void OrbitFinder::set_model(const FrictionSystem& system) { flow_.set_model(system); }

void OrbitFinder::Floquet(Orbit& o, const Mat2& M) const {
  o.has_floquet = true;
  o.monodromy = M;
  Eigen::EigenSolver<Mat2> es(M, false);
  o.eigenvalues[0] = es.eigenvalues()[0];
  o.eigenvalues[1] = es.eigenvalues()[1];
  // One multiplier of an autonomous periodic orbit is 1 (the flow direction).
  if (std::abs(o.eigenvalues[0] - 1.0) > std::abs(o.eigenvalues[1] - 1.0))
    std::swap(o.eigenvalues[0], o.eigenvalues[1]);
}

OrbitResult OrbitFinder::StickSlip(bool first_return_only) {
  const FrictionSystem& m = system();
  const Vec2 exit = m.ExitPoint();
  StopRule stop;
  stop.at_stick = true;
  stop.at_velocity_max = first_return_only;
  stop.t_max = options_.max_return_time;
  const FlowResult r = flow_.Run(0.0, exit, Mode::kSlipBelow, stop, options_.floquet);
  OrbitResult out;
  if (r.status == FlowStatus::kVelocityMax) {
    out.status = OrbitStatus::kMissed;
    out.gap = r.z[1] - m.v();
    out.message = "the first return of the slip phase stays below the belt speed";
    return out;
  }
  if (r.status != FlowStatus::kStick) {
    out.status = FromFlowStatus(r.status);
    std::ostringstream os;
    if (out.status == OrbitStatus::kNoReturn)
      os << "slip from the exit point did not return to the stick set within t = "
         << options_.max_return_time;
    else
      os << r.message;
    out.message = os.str();
    return out;
  }
  Orbit& o = out.orbit;
  o.kind = OrbitKind::kStickSlip;
  CopyExtremes(o, r);
  o.modes.push_back(Mode::kStick);
  o.start = exit;
  o.t_stick = (exit[0] - r.z[0]) / m.v();  // seed eq. (3.6)
  o.period = r.t + o.t_stick;
  if (options_.floquet) {
    // Leaving stick after the stick phase (Phi_stick = I), entering it before.
    const Mat2 M = m.SaltationStickOut() * FrictionSystem::SaltationStickIn() * r.jacobian;
    Floquet(o, M);
    o.multiplier = M.trace() - 1.0;  // the other multiplier is exactly 1
    o.stable = std::abs(o.multiplier) < 1.0;
  } else {
    o.stable = true;  // superstable: S_in removes the x' perturbation
  }
  return out;
}

ReturnMap OrbitFinder::Return(double x, bool derivative) {
  StopRule stop;
  stop.at_section = true;
  stop.at_stick = true;
  stop.t_max = options_.max_return_time;
  ReturnMap map;
  map.flow = flow_.Run(0.0, Vec2(x, 0.0), Mode::kSlipBelow, stop, derivative);
  const FlowResult& r = map.flow;
  map.status = FromFlowStatus(r.status);
  if (r.status == FlowStatus::kSection) {
    map.x = r.z[0];
    map.period = r.t;
    // P' = [(I - f n^T / n^T f) Phi]_11 with n = (0, 1) and f_1 = x' = 0.
    if (derivative) map.dpdx = r.jacobian(0, 0);
    // dP/dp = x_p + x' dT/dp, and x' = 0 on the section: the return time's
    // dependence on p drops out.
    map.has_dpdp = derivative && r.has_dzdp;
    if (map.has_dpdp) map.dpdp = r.dzdp[0];
  } else if (map.status == OrbitStatus::kNoReturn) {
    map.message =
        "no return to the section x' = 0 within t = " + std::to_string(options_.max_return_time);
  } else if (map.status == OrbitStatus::kSticks) {
    map.message = "the trajectory sticks";
  } else {
    map.message = r.message;
  }
  return map;
}

OrbitStatus OrbitFinder::Desingularised(double a, double* g, double* dg, ReturnMap* out) {
  const double xbar = system().SteadySliding().x;
  ReturnMap map = Return(xbar + a, dg != nullptr);
  if (map.status == OrbitStatus::kOk) {
    *g = (map.x - xbar - a) / a;
    if (dg) *dg = (map.dpdx - 1.0 - *g) / a;
  }
  const OrbitStatus s = map.status;
  if (out) *out = std::move(map);
  return s;
}

void OrbitFinder::AcceptPureSlip(Orbit& o, double a, double step, bool stalled,
                                 const ReturnMap& map) const {
  o.newton_stalled = stalled;
  o.newton_step = step;
  o.kind = OrbitKind::kPureSlip;
  o.start = Vec2(system().SteadySliding().x + a, 0.0);
  o.period = map.period;
  CopyExtremes(o, map.flow);
  o.multiplier = map.dpdx;
  if (options_.floquet) Floquet(o, map.flow.jacobian);
  o.stable = std::abs(o.multiplier) < 1.0;
}

namespace {
// A pure-slip iterate outside (kCollapsedAmplitude, a_max) ends the shooting:
// sets the status and its message.
bool LeftRange(double a, double a_max, OrbitResult* out) {
  if (a > a_max) {
    out->status = OrbitStatus::kNotConverged;
    out->message = "pure-slip shooting left the plausible range (a > " + std::to_string(a_max) +
                   "): no pure-slip orbit near the guess";
    return true;
  }
  if (a < Tolerances::kCollapsedAmplitude) {
    out->status = OrbitStatus::kCollapsed;
    out->message = "pure-slip shooting collapsed onto the equilibrium";
    return true;
  }
  return false;
}
}  // namespace

OrbitResult OrbitFinder::PureSlip(double a_guess) {
  if (!(a_guess > 0) || !std::isfinite(a_guess))
    throw InvalidArgument("PureSlip: a_guess = " + std::to_string(a_guess) + " must be > 0");
  OrbitResult out;
  double a = a_guess, a_prev = a_guess, last_da = HUGE_VAL;
  bool polished = false;
  // a came back from an iterate that stuck: never accepted, its step may point
  // past the belt (no orbit there, however small the step at a loose tol).
  bool backtracked = false;
  // A pure-slip orbit below the belt stays within |x'| < v + a bit, so its
  // section amplitude is a few times (v + mu_s) at most.
  const double a_max = Tolerances::kPlausibleAmplitude *
                       std::max(a_guess, system().v() + system().static_limit() + 1);
  ReturnMap map;
  for (int it = 1; it <= options_.max_newton; ++it) {
    out.iterations = it;
    double g = 0, dg = 0;
    const OrbitStatus s = Desingularised(a, &g, &dg, &map);
    if (s == OrbitStatus::kSticks && it < options_.max_newton) {
      // Too large: the trajectory reaches the belt speed. Backtrack towards the
      // last iterate that slipped, or shrink a first guess.
      if (it == 1 || a == a_prev) {
        a_prev = a *= Tolerances::kStickShrink;
      } else {
        a = 0.5 * (a + a_prev);
      }
      backtracked = true;
      continue;
    }
    if (s != OrbitStatus::kOk) {
      out.status = s;
      std::ostringstream os;
      os << "pure-slip shooting at a = " << a << ": " << map.message;
      out.message = os.str();
      return out;
    }
    double da = dg != 0 ? -g / dg : 0.0;
    if (!std::isfinite(da)) da = 0.0;
    // Keep a > 0 (the section point lies right of the equilibrium) and at most
    // double it per step: where G is flat (overdamped sliding, no orbit) an
    // unbounded step would send the shooting off to a ~ 1e14.
    if (a + da < Tolerances::kMinAmplitudeRatio * a) da = -Tolerances::kMaxAmplitudeDrop * a;
    if (da > a) da = a;
    // Converged, or stalled at the integration noise floor.
    const double tol = options_.EffectiveNewtonTol() * std::max(1.0, a);
    const bool converged = !backtracked && std::abs(da) <= tol;
    // The orbit reported is the one at a, off by da: one more step while da is
    // above the integration noise (0.1 rtol).
    const Tolerances tols = Tolerances::From(options_.flow.rtol, options_.flow.atol);
    if (converged && !polished && it < options_.max_newton &&
        std::abs(da) > tols.ShootingPolish(a)) {
      polished = true;
      a += da;
      continue;
    }
    if (converged || (!backtracked && NewtonStalled(std::abs(da), std::abs(last_da), it, tol))) {
      AcceptPureSlip(out.orbit, a, std::abs(da), !converged, map);
      return out;
    }
    a_prev = a;
    last_da = da;
    a += da;
    backtracked = false;
    if (LeftRange(a, a_max, &out)) return out;
  }
  out.status = OrbitStatus::kNotConverged;
  std::ostringstream os;
  os << "pure-slip Newton did not converge in " << options_.max_newton << " steps (a = " << a
     << ")";
  out.message = os.str();
  return out;
}

std::vector<Orbit> OrbitFinder::PureSlipScan(double a_lo, double a_hi, int n) {
  if (!(a_lo > 0 && a_hi > a_lo && n >= 2))
    throw InvalidArgument("PureSlipScan: need 0 < a_lo < a_hi and n >= 2");
  std::vector<Orbit> found;
  double a0 = a_lo, g0 = 0;
  bool ok0 = Desingularised(a0, &g0, nullptr) == OrbitStatus::kOk;
  for (int i = 1; i < n; ++i) {
    const double a1 = a_lo + (a_hi - a_lo) * i / (n - 1);
    double g1 = 0;
    const bool ok1 = Desingularised(a1, &g1, nullptr) == OrbitStatus::kOk;
    if (ok0 && ok1 && g0 * g1 <= 0) {
      auto G = [&](double a) {
        double g = 0;
        return Desingularised(a, &g, nullptr) == OrbitStatus::kOk ? g : NAN;
      };
      const RootResult root = FindRoot(G, a0, a1, g0, g1, Tolerances::kScanBracket * a1);
      if (root.ok) {
        OrbitResult r = PureSlip(root.x);
        if (r.ok()) found.push_back(r.orbit);
      }
    }
    a0 = a1;
    g0 = g1;
    ok0 = ok1;
  }
  return found;
}

OrbitStatus OrbitFinder::GrazingGap(double* gap, FlowResult* run) {
  StopRule stop;
  stop.switching = false;
  stop.at_velocity_max = true;
  stop.t_max = options_.max_return_time;
  FlowResult r = flow_.Run(0.0, system().ExitPoint(), Mode::kSlipBelow, stop,
                           run != nullptr && options_.floquet);
  if (r.status != FlowStatus::kVelocityMax) return FromFlowStatus(r.status);
  *gap = r.z[1] - system().v();
  if (run) *run = std::move(r);
  return OrbitStatus::kOk;
}

}  // namespace stickslip
