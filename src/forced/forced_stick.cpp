// Stick phases of the forced flow: x' = v, x = x_a + v (t - t_a), until the
// force that holds stick, phi(t) = x + 2 beta v - A cos(Omega t), leaves
// [-mu_s, mu_s] (design.md section 5). Each step expands phi in t (cos and sin
// by their two-term recurrences) and finds the first sign change of mu_s -+ phi
// on the step polynomial, none missed (poly_roots.hpp).
#include <cmath>

#include "forced_driver.hpp"

namespace stickslip::forced_detail {
namespace {
// Omega h <= 1 and order 24: the truncated term (Omega h)^25 / 25! < 1e-25 A.
constexpr int kStickOrder = 24;
}  // namespace

bool Driver::Stick() {
  const double v = m_.v(), a = m_.force(), w = m_.omega(), mu_s = m_.static_limit();
  const double t_a = t_, x_a = x_;
  const double t_end = rq_.t_end;
  // At v = 0 the band's edge is never reached while |x| + A < mu_s: held for good.
  if (v == 0 && std::abs(x_a) + a < mu_s) {
    t_ = t_end;
    Sample();
    return true;
  }
  const int n = a > 0 ? kStickOrder : 1;
  while (t_ < t_end) {
    if (run_.steps >= o_.max_steps)
      return Fail(ForcedStatus::kTooMuchWork, "max_steps = " + std::to_string(o_.max_steps));
    ++run_.steps;
    const double h = a > 0 ? std::min(1 / w, t_end - t_) : t_end - t_;
    // phi(t_ + u h) = sum_k p_k u^k.
    double p[kStickOrder + 1], co = std::cos(w * t_), si = std::sin(w * t_), hk = 1;
    p[0] = x_a + v * (t_ - t_a) + 2 * m_.beta() * v - a * co;
    for (int k = 1; k <= n; ++k) {
      const double next_co = -w * si / k, next_si = w * co / k;
      co = next_co, si = next_si;
      hk *= h;
      p[k] = -a * co * hk;
    }
    p[1] += v * h;
    double up[kStickOrder + 1], low[kStickOrder + 1];  // mu_s - phi, mu_s + phi: >= 0 in stick
    for (int k = 0; k <= n; ++k) up[k] = -p[k], low[k] = p[k];
    up[0] += mu_s, low[0] += mu_s;
    const PolyRoot ru = FirstSignChange(up, n, 1, 1), rl = FirstSignChange(low, n, 1, 1);
    if (ru.found || rl.found) {
      const double u = std::min(ru.found ? ru.u : 2.0, rl.found ? rl.u : 2.0);
      const double t = t_ + u * h;
      return Exit(t, x_a + v * (t - t_a));
    }
    t_ = t_ + h == t_end ? t_end : t_ + h;
    x_ = x_a + v * (t_ - t_a);
    Sample();
  }
  return true;
}

bool Driver::Exit(double t, double x) {
  const Mode after = m_.ExitMode(t, x);
  // On the band's edge exactly: phi(t) = +-mu_s, x = +-mu_s - 2 beta v + A cos(Omega t).
  // The stick line there differs by the root's error (about 1e-13); kept, it
  // left x'' = mu_s - phi of that size and either sign at the start of slip,
  // which for a law with mu(0+) = mu_s could send the flow straight back into
  // stick at the same t, over and over ("switching does not advance t").
  const double edge = (after == Mode::kSlipBelow ? 1 : -1) * m_.static_limit() -
                      2 * m_.beta() * m_.v() + m_.force() * std::cos(m_.omega() * t);
  t_ = t, x_ = edge, xd_ = m_.v();
  if (rq_.variational) phi_ = m_.SaltationStickOut(after, t, x) * phi_;
  mode_ = after;
  ++run_.exits;
  if (!Record(ForcedEventKind::kStickOut, Mode::kStick, after)) return false;
  return !(rq_.stop_at_exit > 0 && run_.exits >= rq_.stop_at_exit);
}

}  // namespace stickslip::forced_detail
