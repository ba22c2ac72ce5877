// Independent reference integrator for the belt model (seed eq. 3.5), used by the
// tests and the benchmark to check the CVODE-based library. It shares no physics with the
// library: the friction laws and the slip fields are re-derived here from the seed (3.3), (3.5),
// and stickslip::Params is only an input carrier. Integration is Boost.Odeint's
// Runge-Kutta-Fehlberg 7(8) in long double with step control; every event (arrival at x' = v,
// extrema of x and x') is located by re-stepping from the start of the accepted step and bisecting
// on the step length.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "stickslip/systems/belt/params.hpp"

// Odeint's steppers copy their uninitialized scratch arrays on construction; silence GCC's
// -Wuninitialized about that for odeint and this header only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>

namespace stickslip::reference {

using Real = long double;

// Known answers: closed forms and published values (README, "The seed's claims, tested").
// Leine, van Campen, de Kraker, van den Steen (1998), leine law, beta = 0, mu_s = 1,
// delta = 3, v = 0.2.
inline constexpr Real kLeineXMax = 1.133944669704L;
inline constexpr Real kLeinePeriod = 12.001L;
// The same x_max of the exact Filippov model, from a 30-digit Taylor integration (mpmath odefun)
// of the first slip from (1, 0.2) to x' = 0. The published value is 6.7e-9 lower, presumably
// the tolerance band of the switch model used by Leine et al.
inline constexpr Real kLeineXMaxExact = 1.13394467644165683998L;

// Coulomb law, beta = 0: slip is a circle about x = mu_k of radius sqrt(v^2 + (mu_s - mu_k)^2),
// so T = pi + 2 atan(v / (mu_s - mu_k)) + 2 (mu_s - mu_k) / v.
inline Real CoulombPeriodBeta0(Real mu_s, Real mu_k, Real v) {
  const Real pi = std::acos(Real(-1));
  return pi + 2 * std::atan(v / (mu_s - mu_k)) + 2 * (mu_s - mu_k) / v;
}

// Cubic law: k1 = 3 (mu_s - mu_m) / (2 v_m), k3 = (mu_s - mu_m) / (2 v_m^3) (seed section 3),
// evaluated in long double from the double inputs.
inline Real CubicK1(const Params& p) {
  return 3 * (Real(p.mu_s) - Real(p.mu_m)) / (2 * Real(p.v_m));
}
inline Real CubicK3(const Params& p) {
  const Real vm = p.v_m;
  return (Real(p.mu_s) - Real(p.mu_m)) / (2 * vm * vm * vm);
}

// Hopf point of the cubic law, seed (3.16): v_max = sqrt((k1 - 2 beta) / (3 k3)).
inline Real CubicHopfSpeed(const Params& p) {
  return std::sqrt((CubicK1(p) - 2 * Real(p.beta)) / (3 * CubicK3(p)));
}

// Friction magnitude mu(s), s = |x' - v|, and mu'(s) (README, friction laws). The smooth
// branch is also evaluated at small s < 0 when a step overshoots the switching surface.
struct Law {
  explicit Law(const Params& p)
      : kind(p.law),
        mu_s(p.mu_s),
        mu_k(p.mu_k),
        v_s(p.v_s),
        delta(p.delta),
        k1(CubicK1(p)),
        k3(CubicK3(p)),
        k5(p.k5) {}

  Real Mu(Real s) const {
    switch (kind) {
      case LawKind::kCubic:
        return mu_s - k1 * s + k3 * s * s * s - k5 * s * s * s * s * s;
      case LawKind::kCoulomb:
        return mu_k;
      case LawKind::kStribeck:
        return mu_k + (mu_s - mu_k) * std::exp(-s / v_s);
      case LawKind::kLeine:
        return mu_s / (1 + delta * s);
    }
    return 0;
  }
  Real DMu(Real s) const {
    switch (kind) {
      case LawKind::kCubic:
        return -k1 + 3 * k3 * s * s - 5 * k5 * s * s * s * s;
      case LawKind::kCoulomb:
        return 0;
      case LawKind::kStribeck:
        return -(mu_s - mu_k) / v_s * std::exp(-s / v_s);
      case LawKind::kLeine:
        return -mu_s * delta / ((1 + delta * s) * (1 + delta * s));
    }
    return 0;
  }

  LawKind kind;
  Real mu_s, mu_k, v_s, delta, k1, k3, k5;  // k5: the cubic law's optional quintic term
};

struct Model {
  explicit Model(const Params& p) : law(p), beta(p.beta), v(p.v) {}
  Real StickLow() const { return -law.mu_s - 2 * beta * v; }  // stick: x + 2 beta v >= -mu_s
  Real StickHigh() const { return law.mu_s - 2 * beta * v; }  // and <= mu_s; exit point x0
  Law law;
  Real beta, v;
};

template <std::size_t N>
using State = std::array<Real, N>;

// Smooth slip field of one mode, seed (3.5): x' = y, y' = -x - 2 beta y + F(y - v) with
// F(u) = -sgn(u) mu(|u|); sigma = -1 below the belt (F = +mu(v - y)), +1 above
// (F = -mu(y - v)). With N = 5 it also carries q' = tr J = -2 beta - mu'(s) (trace formula,
// Leine et al. 1998) and the variation (dx, dy) of the state w.r.t. the initial x.
template <std::size_t N>
struct SlipField {
  static_assert(N == 2 || N == 5, "state is (x, y) or (x, y, q, dx, dy)");
  void operator()(const State<N>& s, State<N>& ds, Real /*t*/) const {
    const Real u = sigma * (s[1] - m->v);  // s = |y - v| on the mode's own side
    ds[0] = s[1];
    ds[1] = -s[0] - 2 * m->beta * s[1] - sigma * m->law.Mu(u);
    if constexpr (N == 5) {
      const Real tr = -2 * m->beta - m->law.DMu(u);
      ds[2] = tr;
      ds[3] = s[4];
      ds[4] = -s[3] + tr * s[4];
    }
  }
  State<N> operator()(const State<N>& s) const {
    State<N> ds;
    (*this)(s, ds, 0);
    return ds;
  }
  const Model* m;
  int sigma;
};

// Controlled RKF78 stepper with a step cap (so no two extrema of x' fall into one step) and
// exact re-stepping from a step's start for event location.
template <std::size_t N>
class Stepper {
 public:
  using Rk = boost::numeric::odeint::runge_kutta_fehlberg78<State<N>, Real, State<N>, Real>;

  Stepper(SlipField<N> f, Real tol, Real hmax = 0.1L)
      : f_(f), ctrl_(boost::numeric::odeint::make_controlled<Rk>(tol, tol)), hmax_(hmax) {}

  // Advances (s, t) by one accepted step and returns its length (0 if the control fails).
  Real Step(State<N>& s, Real& t) {
    for (int tries = 0; tries < 200; ++tries) {
      dt_ = std::min(dt_, hmax_);
      const Real t0 = t;
      State<N> out;
      if (ctrl_.try_step(f_, s, t, out, dt_) == boost::numeric::odeint::success) {
        s = out;
        return t - t0;
      }
    }
    return 0;
  }
  // One RKF78 step of length h from (s0, t0), no control: the dense output used for events.
  State<N> From(const State<N>& s0, Real t0, Real h) const {
    if (h == 0) return s0;
    State<N> out;
    Rk rk;
    rk.do_step(f_, s0, t0, out, h);
    return out;
  }
  const SlipField<N>& field() const { return f_; }

 private:
  SlipField<N> f_;
  typename boost::numeric::odeint::result_of::make_controlled<Rk>::type ctrl_;
  Real hmax_;
  Real dt_ = 1e-2L;
};

// Bisection on h in [a, b] for the sign change of a predicate, given its value at a.
// Returns the midpoint of the last bracket, resolved to a few ulps of t0 + h.
template <class Pred>
Real Bisect(const Pred& positive, Real a, Real b, bool pa, Real t0) {
  const Real eps = std::numeric_limits<Real>::epsilon();
  for (int i = 0; i < 300 && b - a > 4 * eps * (std::abs(t0) + std::abs(b) + 1e-3L); ++i) {
    const Real mid = (a + b) / 2;
    if (mid <= a || mid >= b) break;
    (positive(mid) == pa ? a : b) = mid;
  }
  return (a + b) / 2;
}

// Running extremes of x and x' along an orbit.
struct Extremes {
  Real x_min = std::numeric_limits<Real>::infinity(), x_max = -x_min;
  Real xdot_min = x_min, xdot_max = -x_min;
  void Add(Real x, Real y) {
    x_min = std::min(x_min, x), x_max = std::max(x_max, x);
    xdot_min = std::min(xdot_min, y), xdot_max = std::max(xdot_max, y);
  }
};

// Adds to e the extrema inside one step [0, h] from s0 to s1: x at roots of y, y at roots of y'
// (sign changes between the step's ends, located by bisection), and the step end itself.
template <std::size_t N>
void AddStepExtremes(const Stepper<N>& st, const State<N>& s0, Real t0, Real h, const State<N>& s1,
                     Extremes& e) {
  const auto& f = st.field();
  if ((s0[1] > 0) != (s1[1] > 0)) {
    const Real hr =
        Bisect([&](Real hh) { return st.From(s0, t0, hh)[1] > 0; }, 0, h, s0[1] > 0, t0);
    const State<N> r = st.From(s0, t0, hr);
    e.Add(r[0], r[1]);
  }
  const bool p0 = f(s0)[1] > 0;
  if (p0 != (f(s1)[1] > 0)) {
    const Real hr = Bisect([&](Real hh) { return f(st.From(s0, t0, hh))[1] > 0; }, 0, h, p0, t0);
    const State<N> r = st.From(s0, t0, hr);
    e.Add(r[0], r[1]);
  }
  e.Add(s1[0], s1[1]);
}

// Integrates mode sigma from (x, v) until the first arrival at y = v (d = sigma (y - v) falls
// to 0). Near grazing the arrival is an almost tangential touch, so besides sign changes of d
// at step ends it watches the minimum of d (root of d' = sigma y'): if that minimum is <= 0,
// the crossing is located between the step start and the minimum (di Bernardo et al. 2008,
// grazing). The start itself (d = 0) is not an event. Returns false if no arrival before t_max.
inline bool SlipSegment(const Model& m, int sigma, Real x_start, Real tol, Real t_max, Real& t,
                        Real& x_arrival, Extremes& e) {
  Stepper<2> st(SlipField<2>{&m, sigma}, tol);
  const auto& f = st.field();
  State<2> s{x_start, m.v};
  e.Add(s[0], s[1]);
  const Real t_end = t + t_max;
  auto d = [&](const State<2>& z) { return sigma * (z[1] - m.v); };
  for (bool first = true; t < t_end; first = false) {
    const State<2> s0 = s;
    const Real t0 = t;
    const Real h = st.Step(s, t);
    if (h <= 0) return false;
    auto d_at = [&](Real hh) { return d(st.From(s0, t0, hh)) > 0; };
    // At a segment start d = 0 and d' >= 0: both count as positive there.
    const bool dp0 = first ? true : sigma * f(s0)[1] > 0;
    const bool dp1 = sigma * f(s)[1] > 0;
    Real a = 0, b = -1;  // bracket of the first crossing, d(a) > 0 >= d(b)
    if (!dp0 && dp1) {   // minimum of d inside the step
      const Real hm =
          Bisect([&](Real hh) { return sigma * f(st.From(s0, t0, hh))[1] > 0; }, 0, h, false, t0);
      if (!d_at(hm)) {
        b = hm;
      } else if (d(s) <= 0) {
        a = hm, b = h;
      }
    } else if (d(s) <= 0) {
      b = h;
    }
    if (b < 0) {
      AddStepExtremes(st, s0, t0, h, s, e);
      continue;
    }
    const Real he = Bisect(d_at, a, b, true, t0);
    State<2> se = st.From(s0, t0, he);
    se[1] = m.v;
    AddStepExtremes(st, s0, t0, he, se, e);
    t = t0 + he;
    x_arrival = se[0];
    return true;
  }
  return false;
}

struct StickSlipOrbit {
  bool found = false;  // reached the stick set Ω within the limits (else the rest is partial)
  int crossings = 0;   // crossings of x' = v without sticking
  Real period = 0;     // slip time + t_stick
  Real t_stick = 0;    // (x0 - x_arrival) / v
  Real x_arrival = 0;  // x where the orbit enters stick
  Real x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;
};

// The stick-slip orbit through the exit point (x0, v), x0 = mu_s - 2 beta v (seed,
// case 1: the return map on Ω is constant): slip from (x0, v) until the first arrival in Ω,
// crossing x' = v outside the stick interval into the other slip mode, then stick for (x0 - x_a) /
// v.
inline StickSlipOrbit StickSlip(const Params& p, Real tol = 1e-17L, Real t_max = 2000,
                                int max_crossings = 50) {
  const Model m(p);
  StickSlipOrbit o;
  Extremes e;
  Real t = 0, x = m.StickHigh();
  for (int sigma = -1; o.crossings <= max_crossings; sigma = -sigma, ++o.crossings) {
    Real xa = 0;
    if (!SlipSegment(m, sigma, x, tol, t_max, t, xa, e)) break;
    x = xa;
    if (xa >= m.StickLow() && xa <= m.StickHigh()) {
      o.found = true;
      o.x_arrival = xa;
      o.t_stick = (m.StickHigh() - xa) / m.v;
      e.Add(m.StickHigh(), m.v);
      break;
    }
  }
  o.period = t + o.t_stick;
  o.x_min = e.x_min, o.x_max = e.x_max, o.xdot_min = e.xdot_min, o.xdot_max = e.xdot_max;
  return o;
}

// One turn of the smooth slip-below field (the switch ignored) from (x, 0), y decreasing, back
// to y = 0, y decreasing: the return map of that section, its derivative (variation dx at the
// return, since y = 0 there) and the trace integral q = ∮ tr J dt.
struct SectionReturn {
  bool ok = false;
  Real x = 0, dx = 0, q = 0, period = 0;
  Extremes e;
};

inline SectionReturn ReturnToSection(const Model& m, Real x, Real tol, Real t_max) {
  Stepper<5> st(SlipField<5>{&m, -1}, tol);
  State<5> s{x, 0, 0, 1, 0};
  SectionReturn r;
  r.e.Add(x, 0);
  Real t = 0;
  bool seen_up = false;  // passed the x minimum (y rising through 0)
  for (bool first = true; t < t_max; first = false) {
    const State<5> s0 = s;
    const Real t0 = t;
    const Real h = st.Step(s, t);
    if (h <= 0) return r;
    const bool p0 = first ? false : s0[1] > 0;  // the start y = 0 counts as y < 0
    const bool p1 = s[1] > 0;
    if (!p0 && p1) seen_up = true;
    if (!(seen_up && p0 && !p1)) {
      AddStepExtremes(st, s0, t0, h, s, r.e);
      continue;
    }
    const Real he = Bisect([&](Real hh) { return st.From(s0, t0, hh)[1] > 0; }, 0, h, true, t0);
    State<5> se = st.From(s0, t0, he);
    se[1] = 0;
    AddStepExtremes(st, s0, t0, he, se, r.e);
    r.ok = true;
    r.x = se[0], r.q = se[2], r.dx = se[3], r.period = t0 + he;
    return r;
  }
  return r;
}

struct PureSlipOrbit {
  bool found = false;   // Newton converged to a pure-slip orbit
  bool sticks = false;  // the converged orbit reaches x' = v: it would stick (or cross)
  int iterations = 0;
  Real x_section = 0;  // fixed point: x at y = 0, y decreasing (the x maximum)
  Real period = 0;
  Real x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;
  Real multiplier = 0;      // exp(∮ (-2 beta + F'(y - v)) dt), the trace formula
  Real map_derivative = 0;  // P'(x*) from the variational equations: equals the multiplier
};

// Pure-slip periodic orbit by Newton on the return map P of the section y = 0, y decreasing,
// started at (x_guess, 0); x_guess must exceed the steady sliding position mu(v).
inline PureSlipOrbit PureSlip(const Params& p, Real x_guess, Real tol = 1e-17L, Real t_max = 200) {
  const Model m(p);
  const Real x_bar = m.law.Mu(m.v);  // steady sliding: y = 0 is transversal only for x > x_bar
  PureSlipOrbit o;
  Real x = x_guess;
  SectionReturn r;
  for (o.iterations = 1; o.iterations <= 60; ++o.iterations) {
    r = ReturnToSection(m, x, tol, t_max);
    if (!r.ok) return o;
    const Real step = -(r.x - x) / (r.dx - 1);
    if (!std::isfinite(step)) return o;
    if (std::abs(step) <= 1e-15L * (1 + std::abs(x))) {
      o.found = true;
      break;
    }
    Real xn = x + step;
    if (xn <= x_bar) xn = (x + x_bar) / 2;  // keep the section crossing transversal
    x = xn;
  }
  if (!o.found) return o;
  o.x_section = x;
  o.period = r.period;
  o.x_min = r.e.x_min, o.x_max = r.e.x_max, o.xdot_min = r.e.xdot_min, o.xdot_max = r.e.xdot_max;
  o.multiplier = std::exp(r.q);
  o.map_derivative = r.dx;
  if (o.xdot_max >= m.v) o.sticks = true, o.found = false;
  return o;
}

// Maximum of y on the first return of the smooth slip-below field from the exit point (x0, v),
// the switch ignored (the start is itself a maximum of y, since y' = 0 there for mu(0+) = mu_s).
// Returns NaN if no such maximum before t_max.
inline Real FirstReturnMaxXdot(const Model& m, Real tol, Real t_max = 200) {
  Stepper<2> st(SlipField<2>{&m, -1}, tol);
  const auto& f = st.field();
  State<2> s{m.StickHigh(), m.v};
  Real t = 0;
  bool seen_min = false;
  for (bool first = true; t < t_max; first = false) {
    const State<2> s0 = s;
    const Real t0 = t;
    if (st.Step(s, t) <= 0) break;
    const bool p0 = first ? false : f(s0)[1] > 0;
    const bool p1 = f(s)[1] > 0;
    if (!p0 && p1) seen_min = true;
    if (seen_min && p0 && !p1) {
      const Real hm =
          Bisect([&](Real hh) { return f(st.From(s0, t0, hh))[1] > 0; }, 0, t - t0, true, t0);
      return st.From(s0, t0, hm)[1];
    }
  }
  return std::numeric_limits<Real>::quiet_NaN();
}

// Grazing belt speed: the v in [lo, hi] where the slip phase from (x0, v) returns to x' = v
// tangentially and the stick phase vanishes. Bisection on sign(FirstReturnMaxXdot - v) down to
// v_tol. Returns NaN if the sign does not change over [lo, hi].
inline Real GrazingSpeed(Params p, Real lo, Real hi, Real v_tol = 1e-13L, Real tol = 1e-17L) {
  auto g = [&](Real v) {
    Model m(p);
    m.v = v;
    return FirstReturnMaxXdot(m, tol) - v;
  };
  const Real g_lo = g(lo), g_hi = g(hi);
  if (!(g_lo * g_hi <= 0)) return std::numeric_limits<Real>::quiet_NaN();
  const bool p_lo = g_lo > 0;
  while (hi - lo > v_tol) {
    const Real mid = (lo + hi) / 2;
    (((g(mid) > 0) == p_lo) ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

}  // namespace stickslip::reference

#pragma GCC diagnostic pop
