// The forced oscillator's Taylor slip stepper (forced_stepper.hpp): one step
// of SlipSeries at a time, its arrival on x' = v as the first sign change of
// the step polynomial of x' - v (none missed: poly_roots.hpp), the extrema of
// x and x' as the roots of x' and x'' before it.
#include "forced_stepper.hpp"

#include <algorithm>
#include <cmath>

namespace stickslip::forced_detail {

StepOutcome ForcedTaylorStepper::Advance(double tout, double* t) {
  const double t_end = std::min(tout, tstop_);
  for (;;) {
    *t = t_;
    if (t_ >= t_end) return StepOutcome::kReached;
    if (steps_ >= p_->max_steps) {
      error_ = "max_steps";
      return StepOutcome::kTooMuchWork;
    }
    const Step s = TakeStep(t_end);
    *t = t_;
    if (s == Step::kFailed) return StepOutcome::kFailed;
    if (s == Step::kArrived) return StepOutcome::kRoot;
    if (p_->cancel && (*p_->cancel)()) return StepOutcome::kCancelled;
  }
}

inline double ForcedTaylorStepper::Arrival(const double* g, int n, double h) {
  int d = n;
  double gd[kMaxOrder + 1];
  if (on_surface_) {
    d = Deflate(g, n);
    // x'' h, the deflated constant term, is rounding at a stick exit with
    // mu(0+) = mu_s (x'' = 0 there); Deflate's noise, relative to the
    // polynomial (O(h^2) on a short step), may keep it, and its sign must
    // not count: it sent the flow back into stick at the same t, over and over.
    const ForcedModel& m = *p_->model;
    const double scale = 1 + std::abs(y_[0]) + std::abs(y_[1]) + m.force() + m.static_limit();
    if (d >= 1 && std::abs(g[0]) <= Tolerances::SurfaceRounding() * scale * h) {
      std::copy(g, g + d + 1, gd);
      gd[0] = 0;
      g = gd;
    }
  }
  on_surface_ = false;
  if (d < 0 || !arrive_) return 2;
  const int side = -p_->Toward();  // the sign of x' - v in this mode
  const int s0 = g[0] > 0 ? 1 : (g[0] < 0 ? -1 : side);
  if (s0 != side) return 0;  // on the other side already (rounding at the last step's end)
  const PolyRoot r = FirstSignChange(g, d, side, side);
  return r.found ? r.u : 2;
}

// The roots of x' (g0 with its constant xd0) and of x'' (g2) before u_end,
// each to the problem's hook if an event asks for it.
inline void ForcedTaylorStepper::Extrema(double* g0, double xd0, const double* g2, int n,
                                         double u_end, double h) {
  double out[6];
  int g = 0;
  auto extremum = [&](double u, int direction) {
    if (u >= u_end) return false;
    if (!p_->on_event.fn || !p_->Passes(g, direction)) return true;
    series_.Evaluate(u * h, out);
    p_->on_event(g, out);
    return true;
  };
  if (watch_x_) {
    g = 2;
    g0[0] = xd0;
    EachRoot(g0, n, xd0 > 0 ? 1 : -1, 1, extremum);
  }
  if (watch_xd_) {
    g = 1;
    EachRoot(g2, n - 1, g2[0] > 0 ? 1 : -1, 1, extremum);
  }
}

ForcedTaylorStepper::Step ForcedTaylorStepper::TakeStep(double t_end) {
  series_.Expand(p_->mode, t_, y_, p_->variational);
  const int n = series_.order();
  double h = series_.StepSize();
  if (std::isnan(h)) return error_ = "non-finite Taylor coefficients", Step::kFailed;
  h = std::min(h, t_end - t_);
  if (!(h > 0) || t_ + h == t_) return error_ = "step-size underflow", Step::kFailed;
  ++steps_;
  // The events' polynomials in u = tau / h: x' - v, x', x''.
  const double* xd = series_.coeff(1);
  double g0[kMaxOrder + 1], g2[kMaxOrder + 1];
  double hk = 1;
  for (int k = 0; k <= n; ++k, hk *= h) g0[k] = xd[k] * hk;
  if (watch_xd_) {  // x'' only for the extrema of x'
    hk = 1;
    for (int k = 0; k <= n; ++k, hk *= h) g2[k] = k < n ? (k + 1) * xd[k + 1] * hk : 0.0;
  }
  const double xd0 = g0[0];
  g0[0] -= v_;
  const double u_hit = Arrival(g0, n, h);
  if (watch_x_ || watch_xd_) Extrema(g0, xd0, g2, n, std::min(u_hit, 1.0), h);
  const bool hit = u_hit <= 1;
  const double tau = hit ? u_hit * h : h;
  series_.Evaluate(tau, y_);
  if (!hit) {
    t_ = t_ + h == t_end ? t_end : t_ + h;
    if (p_->on_step.fn) p_->on_step(t_, y_);
    return Step::kOn;
  }
  t_ = t_ + tau;
  rf0_ = p_->Toward();
  on_surface_ = true;  // if the loop goes on from here
  return Step::kArrived;
}

}  // namespace stickslip::forced_detail
