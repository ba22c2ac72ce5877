// The independent reference point of a forced branch's row (forced_reference.hpp,
// long double): the m = 1 orbit nearest the row on the reference's own curve.
// The curve is solved on the stroboscopic section at the phase theta_s in the
// middle of the row's longest slip phase (the map is smooth there; a start in
// stick at phase 0 would collapse the state), as G(w, Omega) = P_s(w; Omega) - w
// = 0 in (w, Omega), with the component of the curve's tangent largest in modulus
// held at the row's value (Omega away from folds; a state component near one,
// where the state at fixed Omega is ill-conditioned, ~ 1 / |1 - mu|). The
// multipliers are DP_s's (DP_0's nonzero ones: DP_0 = B A and DP_s = A B) by
// sixth-order central differences of P_s (FixedStepPiece: a smooth map); x_max, x_min by bisection
// on x' = 0 in slip (PieceSim::exact_extremes) and at the events.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include "forced_reference.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip::forced_reference {

// Boost.Odeint's RKF78 (OdeintPiece's) at the fixed step kH from the piece's
// start: the map is then smooth in the start state (no step control choosing
// other steps for a perturbed start), as its difference quotients need.
struct FixedStepPiece {
  static constexpr Real kH = 5e-3L;
  OdeintPiece::Field f;
  Real t0;
  std::vector<reference::State<2>> zs;
  OdeintPiece::Rk rk;
  FixedStepPiece(const Setup& s, int sigma, Real t0_, Real x0, Real y0)
      : f{&s, sigma}, t0(t0_), zs{{x0, y0}} {}
  void At(Real t, Real& x, Real& y) {
    const size_t k = static_cast<size_t>(std::max(Real(0), std::floor((t - t0) / kH)));
    while (zs.size() <= k) {
      reference::State<2> out;
      rk.do_step(f, zs.back(), t0 + (zs.size() - 1) * kH, out, kH);
      zs.push_back(out);
    }
    reference::State<2> out = zs[k];
    const Real tk = t0 + k * kH;
    if (t > tk) rk.do_step(f, zs[k], tk, out, t - tk);
    x = out[0], y = out[1];
  }
};

struct CurvePoint {
  bool ok = false;
  int fixed = 2;  // the component held: 0 w_x, 1 w_y (near a fold), 2 Omega
  Real omega = 0, x0 = 0, xdot0 = 0, x_max = 0, x_min = 0;
  std::array<std::complex<Real>, 2> mu;  // by modulus, the largest first
  Real phase = 0, w[2] = {0, 0};         // the section's phase and point there
};

template <class Piece>
class CurveReference {
 public:
  using V2 = Eigen::Matrix<Real, 2, 1>;
  using V3 = Eigen::Matrix<Real, 3, 1>;
  using M2 = Eigen::Matrix<Real, 2, 2>;
  // The time grid of the event scans.
  static constexpr Real kDt = 2e-2L;
  Real mu_step = 1e-4L;  // the multipliers' difference step (relative)

  explicit CurveReference(const ForcedBeltParams& p)
      : law_(p.base), beta_(p.base.beta), v_(p.base.v), a_(p.force) {}

  // The difference step of Near's Newton is 1e-8; where the row lies within
  // that of an edge of its family (a sliding point: the map jumps there),
  // 1e-11 too (long double leaves 1e-8 of the Jacobian's digits).
  CurvePoint Near(const OrbitRow& r) const {
    const CurvePoint c = Near(r, 1e-8L);
    return c.ok ? c : Near(r, 1e-11L);
  }

  CurvePoint Near(const OrbitRow& r, Real step) const {
    CurvePoint out;
    const Real w = r.p;
    const Real ths = SlipMiddle(w, r.start.z[0], r.start.z[1]);
    Leg l = Run(w, 0, r.start.z[0], r.start.z[1], ths);
    V3 u(l.x, l.y, w);
    // Forward differences for the chord Newton and the tangent.
    Eigen::Matrix<Real, 2, 3> j;
    V2 g = G(u, ths);
    for (int c = 0; c < 3; ++c) {
      V3 e = u;
      const Real h = step * std::max(Real(1), std::abs(u[c]));
      e[c] += h;
      j.col(c) = (G(e, ths) - g) / h;
    }
    const V3 t = V3(j.row(0).transpose()).cross(V3(j.row(1).transpose()));
    t.cwiseAbs().maxCoeff(&out.fixed);
    const int c0 = out.fixed == 0 ? 1 : 0, c1 = out.fixed == 2 ? 1 : 2;
    M2 a;
    a << j(0, c0), j(0, c1), j(1, c0), j(1, c1);
    const M2 inv = a.inverse();
    for (int it = 0; it < 8; ++it) {
      const V2 d = -inv * g;
      u[c0] += d[0], u[c1] += d[1];
      g = G(u, ths);
      if (d.cwiseAbs().maxCoeff() < 1e-18L) break;
    }
    if (!(g.cwiseAbs().maxCoeff() < 1e-15L)) return out;
    out.omega = u[2];
    out.phase = ths, out.w[0] = u[0], out.w[1] = u[1];
    out.mu = Multipliers(out, mu_step);
    // The strobe point (phase 2 pi = 0) and the extremes over one period.
    const Leg a1 = Run(u[2], ths, u[0], u[1], 2 * Pi(), true);
    const Leg a2 = Run(u[2], 2 * Pi(), a1.x, a1.y, 2 * Pi() + ths, true);
    out.x0 = a1.x, out.xdot0 = a1.y;
    out.x_max = std::max(a1.x_max, a2.x_max), out.x_min = std::min(a1.x_min, a2.x_min);
    out.ok = true;
    return out;
  }

  // DP_s at the point c by sixth-order central differences of step h
  // (relative): its eigenvalues.
  std::array<std::complex<Real>, 2> Multipliers(const CurvePoint& c, Real step) const {
    const V3 u(c.w[0], c.w[1], c.omega);
    const Real ths = c.phase;
    M2 dp;
    for (int c = 0; c < 2; ++c) {
      const Real h = step * std::max(Real(1), std::abs(u[c]));
      V2 col = V2::Zero();
      const Real wt[6] = {1, -9, 45, -45, 9, -1}, k[6] = {3, 2, 1, -1, -2, -3};
      for (int i = 0; i < 6; ++i) {
        V3 e = u;
        e[c] += k[i] * h;
        col += wt[i] * (G(e, ths) + e.template head<2>());
      }
      dp.col(c) = col / (60 * h);
    }
    const Real tr = dp.trace(), det = dp.determinant(), disc = tr * tr / 4 - det;
    const std::complex<Real> root = std::sqrt(std::complex<Real>(disc, 0));
    std::complex<Real> m0 = tr / 2 + root, m1 = tr / 2 - root;
    if (std::abs(m1) > std::abs(m0)) std::swap(m0, m1);
    return {m0, m1};
  }

 private:
  struct Leg {
    Real x, y, x_max, x_min;
    std::vector<Event> events;
  };
  static Real Pi() { return std::acos(Real(-1)); }

  // From (x, x') at phase th0 to phase th1 > th0 at forcing frequency w.
  Leg Run(Real w, Real th0, Real x, Real y, Real th1, bool extremes = false) const {
    PieceSim<Piece> sim(Setup{law_, beta_, v_, a_, w});
    sim.dt = kDt;
    sim.exact_extremes = extremes;
    Real t = th0 / w;
    sim.Run(t, x, y, th1 / w);
    return {x, y, sim.x_max, sim.x_min, sim.events};
  }

  V2 G(const V3& u, Real ths) const {
    const Leg l = Run(u[2], ths, u[0], u[1], ths + 2 * Pi());
    return V2(l.x - u[0], l.y - u[1]);
  }

  // The phase in the middle of the row's longest slip phase (pi without events).
  Real SlipMiddle(Real w, Real x, Real y) const {
    const std::vector<Event> ev = Run(w, 0, x, y, 2 * Pi()).events;
    Real best = -1, mid = Pi();
    const Real period = 2 * Pi() / w;
    for (size_t i = 0; i < ev.size(); ++i) {
      if (ev[i].kind == 0) continue;  // a stick phase follows
      const Real end = i + 1 < ev.size() ? ev[i + 1].t : ev[0].t + period;
      if (end - ev[i].t > best) best = end - ev[i].t, mid = (ev[i].t + end) / 2;
    }
    return std::fmod(mid * w, 2 * Pi());
  }

  reference::Law law_;
  Real beta_, v_, a_;
};

}  // namespace stickslip::forced_reference
