// The forced flow's driver: slip phases by Taylor steps, their arrival on
// x' = v as the first sign change of the step polynomial of x' - v (none
// missed: poly_roots.hpp), the extrema of x and x' as the roots of x' and x''
// on each step, and the Filippov rule at every arrival.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "forced_driver.hpp"
#include "stickslip/errors.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

const char* ForcedEventName(ForcedEventKind k) { return Name(k); }

const char* ForcedStatusName(ForcedStatus s) { return Name(s); }

std::string ForcedOptions::ValidationError() const {
  using T = Tolerances;
  const std::string range = " must lie in [" + Num(T::kAtolMin) + ", " + Num(T::kTolMax) + "]";
  if (!(rtol >= T::kForcedRtolMin && rtol <= T::kTolMax))
    return "rtol = " + Num(rtol) + " must lie in [" + Num(T::kForcedRtolMin) + ", " +
           Num(T::kTolMax) + "]";
  if (!(atol >= T::kAtolMin && atol <= T::kTolMax)) return "atol = " + Num(atol) + range;
  if (max_steps < 1) return "max_steps = " + std::to_string(max_steps) + " must be >= 1";
  if (max_events < 1) return "max_events = " + std::to_string(max_events) + " must be >= 1";
  if (integrator == Integrator::kCvode && !(rtol >= T::kCvodeRtolMin && atol >= T::kCvodeAtolMin))
    return "rtol = " + Num(rtol) + ", atol = " + Num(atol) + ": CVODE needs rtol >= " +
           Num(T::kCvodeRtolMin) + " and atol >= " + Num(T::kCvodeAtolMin);
  return "";
}

ForcedPoint ForcedStart(const ForcedModel& m, double t, double x, double xdot) {
  ForcedPoint p{t, x, xdot, Mode::kSlipBelow};
  if (xdot > m.v()) p.mode = Mode::kSlipAbove;
  if (xdot == m.v()) p.mode = m.InStickBand(t, x) ? Mode::kStick : m.ExitMode(t, x);
  return p;
}

ForcedFlow::ForcedFlow(const ForcedModel& model, const ForcedOptions& options)
    : model_(model), options_(options) {
  const std::string e = options.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
}

ForcedRun ForcedFlow::Run(const ForcedPoint& start, const ForcedRequest& request) const {
  if (!(request.t_end >= start.t) || !std::isfinite(request.t_end))
    throw InvalidArgument("t_end = " + Num(request.t_end) +
                          " must be finite and >= t = " + Num(start.t));
  if (options_.integrator == Integrator::kCvode && request.extremes)
    throw InvalidArgument("extremes inside steps need the Taylor integrator");
  if (!request.switching && start.mode == Mode::kStick)
    throw InvalidArgument("a run without switching needs a slip start");
  ForcedRun run;
  forced_detail::Driver(model_, options_, request, run).Run(start);
  return run;
}

namespace forced_detail {

void Driver::Run(const ForcedPoint& start) {
  t_ = start.t, x_ = start.x, xd_ = start.xdot, mode_ = start.mode;
  if (mode_ == Mode::kStick) {
    xd_ = m_.v();
    phi_ << 1, 0, 0, 0;  // stick has no x' direction
  }
  on_surface_ = xd_ == m_.v();  // a slip start on x' = v (a stick exit): no event there
  run_.extrema.Add(x_, xd_);
  Sample();
  while (t_ < rq_.t_end && (mode_ == Mode::kStick ? Stick() : Slip())) {
  }
  run_.end = {t_, x_, xd_, mode_};
  run_.jacobian = phi_;
}

bool Driver::Fail(ForcedStatus s, const std::string& what) {
  std::ostringstream os;
  os << what << " at t = " << Num(t_, 17);
  run_.status = s;
  run_.message = os.str();
  return false;
}

bool Driver::Record(ForcedEventKind kind, Mode before, Mode after) {
  run_.extrema.Add(x_, xd_);
  if (rq_.events) rq_.events->push_back({kind, t_, x_, before, after});
  Sample();
  stalled_events_ = t_ == last_event_t_ ? stalled_events_ + 1 : 0;
  last_event_t_ = t_;
  if (stalled_events_ > 8) return Fail(ForcedStatus::kFailed, "switching does not advance t");
  if (++events_ > o_.max_events)
    return Fail(ForcedStatus::kTooMuchWork, "max_events = " + std::to_string(o_.max_events));
  return true;
}

bool Driver::Arrive(double t, double x) {
  t_ = t, x_ = x, xd_ = m_.v();
  const Mode before = mode_, after = m_.ModeAfterArrival(mode_, t, x);
  on_surface_ = true;
  if (after == Mode::kStick) {
    phi_.row(1).setZero();  // S_in = diag(1, 0)
    mode_ = after;
    ++run_.sticks;
    return Record(ForcedEventKind::kStickIn, before, after);
  }
  if (after == before) return Record(ForcedEventKind::kTouch, before, after);
  if (rq_.variational) phi_ = m_.SaltationCrossing(before, after, t, x) * phi_;
  mode_ = after;
  ++run_.crossings;
  return Record(ForcedEventKind::kCrossing, before, after);
}

bool Driver::Slip() {
  if (o_.integrator == Integrator::kCvode) return SlipByCvode();
  while (t_ < rq_.t_end && mode_ != Mode::kStick) {
    if (run_.steps >= o_.max_steps)
      return Fail(ForcedStatus::kTooMuchWork, "max_steps = " + std::to_string(o_.max_steps));
    if (!SlipStep(rq_.t_end)) return false;
    if (rq_.stop_at_exit > 0 && run_.exits >= rq_.stop_at_exit) return false;
  }
  return true;
}

bool Driver::SlipStep(double t_end) {
  double z[6] = {x_, xd_, phi_(0, 0), phi_(1, 0), phi_(0, 1), phi_(1, 1)};
  series_.Expand(mode_, t_, z, rq_.variational);
  const int n = series_.order();
  double h = series_.StepSize();
  if (std::isnan(h)) return Fail(ForcedStatus::kFailed, "non-finite Taylor coefficients");
  h = std::min(h, t_end - t_);
  if (!(h > 0) || t_ + h == t_) return Fail(ForcedStatus::kFailed, "step-size underflow");
  ++run_.steps;
  // The events' polynomials in u = tau / h: x' - v, x', x''.
  const double* xd = series_.coeff(1);
  double g0[kMaxOrder + 1], g2[kMaxOrder + 1];
  double hk = 1;
  for (int k = 0; k <= n; ++k, hk *= h) g0[k] = xd[k] * hk;
  if (rq_.extremes) {  // x'' only for the extrema of x'
    hk = 1;
    for (int k = 0; k <= n; ++k, hk *= h) g2[k] = k < n ? (k + 1) * xd[k + 1] * hk : 0.0;
  }
  const double xd0 = g0[0];
  g0[0] -= m_.v();
  const int side = mode_ == Mode::kSlipBelow ? -1 : 1;  // the sign of x' - v in this mode
  double u_hit = 2;
  const double* g = g0;
  int d = n;
  double gd[kMaxOrder + 1];
  if (on_surface_) {
    d = Deflate(g, n);
    // x'' h, the deflated constant term, is rounding at a stick exit with
    // mu(0+) = mu_s (x'' = 0 there); Deflate's noise, relative to the
    // polynomial (O(h^2) on a short step), may keep it, and its sign must
    // not count: it sent the flow back into stick at the same t, over and over.
    const double scale = 1 + std::abs(x_) + std::abs(xd_) + m_.force() + m_.static_limit();
    if (d >= 1 && std::abs(g[0]) <= Tolerances::SurfaceRounding() * scale * h) {
      std::copy(g, g + d + 1, gd);
      gd[0] = 0;
      g = gd;
    }
  }
  on_surface_ = false;
  if (d >= 0 && rq_.switching) {
    const int s0 = g[0] > 0 ? 1 : (g[0] < 0 ? -1 : side);
    if (s0 != side) {
      u_hit = 0;  // on the other side already (rounding at the last step's end)
    } else {
      const PolyRoot r = FirstSignChange(g, d, side, side);
      if (r.found) u_hit = r.u;
    }
  }
  const double u_end = std::min(u_hit, 1.0);
  double out[6];
  auto extremum = [&](double u, int) {
    if (u >= u_end) return false;
    series_.Evaluate(u * h, out);
    run_.extrema.Add(out[0], out[1]);
    return true;
  };
  if (rq_.extremes && m_.v() != 0) {  // x extrema (at v = 0 they are the arrivals)
    g0[0] = xd0;
    EachRoot(g0, n, xd0 > 0 ? 1 : -1, 1, extremum);
  }
  if (rq_.extremes) EachRoot(g2, n - 1, g2[0] > 0 ? 1 : -1, 1, extremum);
  const bool hit = u_hit <= 1;
  const double tau = hit ? u_hit * h : h;
  series_.Evaluate(tau, out);
  if (rq_.variational) phi_ << out[2], out[4], out[3], out[5];
  if (!hit) {
    t_ = t_ + h == t_end ? t_end : t_ + h;
    x_ = out[0], xd_ = out[1];
    run_.extrema.Add(x_, xd_);
    Sample();
    return true;
  }
  return Arrive(t_ + tau, out[0]);
}

}  // namespace forced_detail
}  // namespace stickslip
