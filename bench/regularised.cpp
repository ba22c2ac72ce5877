#include "regularised.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "integrate/cvode.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/friction.hpp"

namespace bench {

namespace {

// One integration of the smooth field, stopped at the n-th maximum of x.
struct Segment {
  double t = 0, x = 0;  // time and x at the last maximum
  double x_min = std::numeric_limits<double>::infinity();
  bool touches = false;  // x' reached v - touch_margin in the last cycle
};

class SmoothBelt {
 public:
  SmoothBelt(const stickslip::Params& p, const SmoothOptions& o)
      : friction_(p),
        two_beta_(2 * p.beta),
        v_(p.v),
        eps_(o.eps),
        touch_margin_(10 * o.eps + 1e-6),
        max_time_(o.max_time),
        cv_(2, stickslip::Method::kBdf, o.rtol, o.atol, o.max_steps, &SmoothBelt::Rhs, 2,
            &SmoothBelt::Roots, this) {}

  // Steady sliding of the smooth model: x = F_eps(-v) = tanh(v / eps) mu(v).
  double SteadySliding() const { return std::tanh(v_ / eps_) * friction_.Mu(v_); }

  // From (x0, y0) to the n-th point where x' crosses 0 downwards (a maximum
  // of x). x_min is located as a root (x' = 0 upwards); "touches" records a
  // crossing of x' = v - touch_margin since the last maximum (the creep that
  // replaces sticking). A root of x'' would be ill-posed in creep (x'' ~ 0).
  bool ToMaximum(double x0, double y0, int n, Segment* s, std::string* why) {
    double y[2] = {x0, y0};
    cv_.Reinit(0.0, y);
    cv_.SetStopTime(max_time_);
    *s = Segment();
    int maxima = 0;
    for (;;) {
      double t = 0;
      const int flag = cv_.Advance(max_time_, &t);
      const double* z = cv_.y();
      if (flag < 0 || flag != CV_ROOT_RETURN) {
        steps_ += cv_.steps();
        std::ostringstream os;
        if (flag >= 0)
          os << "no maximum of x within t = " << max_time_;
        else if (std::abs(last_max_ - SteadySliding()) < 1e-3)
          os << "decays to steady sliding (no cycle)";
        else
          os << "CVODE BDF failed (flag " << flag << "): " << cv_.last_error();
        *why = os.str();
        return false;
      }
      int rf[2];
      cv_.RootInfo(rf);
      if (rf[1] != 0) s->touches = true;
      if (rf[0] > 0) s->x_min = std::min(s->x_min, z[0]);  // x' = 0 upwards
      if (rf[0] < 0) {                                     // x' = 0 downwards
        last_max_ = z[0];
        if (++maxima == n) {
          s->t = t;
          s->x = z[0];
          steps_ += cv_.steps();
          return true;
        }
        s->x_min = std::numeric_limits<double>::infinity();
        s->touches = false;
      }
    }
  }

  long steps() const { return steps_; }

 private:
  double Accel(double x, double y) const {
    const double u = y - v_;
    return -x - two_beta_ * y - std::tanh(u / eps_) * friction_.Mu(std::abs(u));
  }
  static int Rhs(double, N_Vector y, N_Vector ydot, void* data) {
    const auto* self = static_cast<const SmoothBelt*>(data);
    const double* z = N_VGetArrayPointer(y);
    double* f = N_VGetArrayPointer(ydot);
    f[0] = z[1];
    f[1] = self->Accel(z[0], z[1]);
    return 0;
  }
  // g0 = x': the section, and the extrema of x; g1: x' at the touch level.
  static int Roots(double, N_Vector y, double* g, void* data) {
    const auto* self = static_cast<const SmoothBelt*>(data);
    g[0] = N_VGetArrayPointer(y)[1];
    g[1] = g[0] - (self->v_ - self->touch_margin_);
    return 0;
  }

  stickslip::Friction friction_;
  double two_beta_, v_, eps_, touch_margin_, max_time_;
  stickslip::Cvode cv_;
  long steps_ = 0;
  double last_max_ = 0;  // x at the last maximum passed
};

}  // namespace

SmoothCycle RegularisedCycle(const stickslip::Params& p, const SmoothOptions& o) {
  SmoothCycle c;
  SmoothBelt belt(p, o);
  const double xbar = belt.SteadySliding();
  auto fail = [&](const std::string& why) {
    c.ok = false;
    c.message = why;
    c.steps = belt.steps();
    return c;
  };
  // Transient from rest: its last maximum of x is the first shooting guess.
  Segment s;
  std::string why;
  if (!belt.ToMaximum(0.0, 0.0, o.transient_maxima, &s, &why)) return fail("transient: " + why);
  double x = s.x;
  // Newton on P(x) - x (one-dimensional shooting with the period free, since
  // the section fixes the phase); P' by a forward difference with a step
  // balanced against the integration error, sqrt(rtol).
  double last_dx = HUGE_VAL;
  for (int it = 1; it <= o.max_newton; ++it) {
    c.newton = it;
    if (std::abs(x - xbar) < 1e-5) return fail("shooting collapsed onto steady sliding (no cycle)");
    Segment r0, r1;
    if (!belt.ToMaximum(x, 0.0, 1, &r0, &why)) return fail("return map: " + why);
    const double h = std::sqrt(o.rtol) * std::max(0.1, std::abs(x));
    if (!belt.ToMaximum(x + h, 0.0, 1, &r1, &why)) return fail("return map: " + why);
    const double res = r0.x - x, dres = (r1.x - x - h - res) / h;
    double dx = dres != 0 ? -res / dres : 0.0;
    const double tol = 10 * o.rtol * std::max(1.0, std::abs(x));
    const bool stalled =
        it > 3 && std::abs(dx) < 1e3 * tol && std::abs(dx) > 0.5 * std::abs(last_dx);
    if (std::abs(dx) <= tol || stalled) {
      c.ok = true;
      c.period = r0.t;
      c.x_max = std::max(x, r0.x);
      c.x_min = r0.x_min;
      c.touches = r0.touches;
      c.steps = belt.steps();
      return c;
    }
    // Keep the section point right of steady sliding (transversal section).
    if (x + dx <= xbar) dx = 0.5 * (xbar - x);
    last_dx = dx;
    x += dx;
  }
  return fail("shooting did not converge in " + std::to_string(o.max_newton) + " steps");
}

}  // namespace bench
