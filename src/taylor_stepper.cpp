// The Taylor stepper for one slip mode: coefficients of z (and Phi) by
// recurrences, order and step from the tolerance (Jorba & Zou 2005, Exp. Math.
// 14, section 3.2, with heyoka's safety factor, Biscani & Izzo 2021, eq. 10),
// events as the first sign changes of the step polynomials (poly_roots.hpp);
// the step polynomial is the dense output.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "mu_series.hpp"
#include "poly_roots.hpp"
#include "series.hpp"
#include "stepper.hpp"

namespace stickslip {
namespace {

constexpr int kMaxOrder = 36;
constexpr Reciprocals<kMaxOrder> kInverse;

// JZ (3.8): order p = ceil(-ln(eps) / 2 + 1).
int OrderFor(double eps) {
  return std::min(kMaxOrder, static_cast<int>(std::ceil(-0.5 * std::log(eps) + 1.0)));
}

class TaylorStepper final : public Stepper {
 public:
  TaylorStepper(const FlowOptions& o, bool variational)
      : rtol_(o.rtol),
        atol_(o.atol),
        max_steps_(o.max_steps),
        n_(variational ? 6 : 2),
        order_rel_(OrderFor(o.rtol)),
        order_abs_(OrderFor(o.atol)) {}

  void Reset(const SlipProblem& problem, double t0, const double* y0) override {
    p_ = problem;
    sigma_ = p_.mode == Mode::kSlipBelow ? 1 : -1;
    mu_.emplace(p_.model->friction());
    s_.Clear();
    cc_.Clear();
    for (auto& row : c_) std::fill(row, row + kMaxOrder + 1 + kPad, 0.0);
    std::copy(y0, y0 + n_, yend_);
    std::copy(y0, y0 + n_, y_);
    ta_ = tb_ = t_ = t0;
    tstop_ = INFINITY;
    steps_ = 0;
    pending_ = passed_root_ = false;
    for (auto& s : state_) s = kFresh;
  }
  void SetStopTime(double t) override { tstop_ = t; }
  StepOutcome Advance(double tout, double* t) override;
  const double* y() const override { return y_; }
  void RootInfo(int* rf) const override { std::copy(rf_, rf_ + kNumRoots, rf); }
  bool Interpolate(double t, double* out) override {
    const double slack = 4e-16 * std::max(1.0, std::abs(t));
    if (!(t >= ta_ - slack && t <= tb_ + slack)) return false;
    Evaluate(t - ta_, out);
    return true;
  }
  double LastStepStart() override { return ta_; }
  double CurrentTime() override { return tb_; }
  long steps() const override { return steps_; }
  int size() const override { return n_; }
  const std::string& last_error() const override { return error_; }

 private:
  enum SignState { kFresh, kTracked, kDeflate, kInactive };
  // The roots of one step: the first that stops (rf, first), and the
  // extrema passed on the way.
  struct Roots {
    double first = 2;
    int rf[kNumRoots] = {0, 0, 0};
    struct Passed {
      double u;
      int i;
    } passed[2 * kMaxOrder + 8];
    int n_passed = 0;
    // Returns whether the root stops.
    bool Add(int i, double u, int direction, bool stops) {
      if (!stops) {
        if (n_passed < static_cast<int>(sizeof passed / sizeof passed[0]))
          passed[n_passed++] = {u, i};
        return false;
      }
      if (u > first) return true;
      if (u < first) std::fill(rf, rf + kNumRoots, 0);
      first = u;
      rf[i] = direction;
      return true;
    }
  };
  void EventRoots(int i, const double* gi, int deg, Roots& roots);

  bool NewStep();
  void Coefficients(int order);
  template <LawKind L, bool Var>
  void Recurrences(int order);
  double StepSize(int order) const;
  void Events(double h);
  void Evaluate(double tau, double* out) const {
    for (int i = 0; i < n_; ++i) out[i] = Horner(c_[i], order_, tau);
  }
  bool Failed(const std::string& what) {
    std::ostringstream os;
    os << "taylor: " << what << " at t = " << ta_;
    error_ = os.str();
    return false;
  }

  double rtol_, atol_;
  long max_steps_;
  int n_, order_rel_, order_abs_;
  int order_ = 0;
  SlipProblem p_;
  int sigma_ = 1;  // F = sigma mu(s), s = sigma (v - x')
  // This step's Taylor coefficients, kPad finite entries past the order for
  // Cauchy(); the series of s = sigma (v - x'), of -2 beta - mu'(s), of mu.
  double c_[6][kMaxOrder + 1 + kPad];
  Series<kMaxOrder> s_, cc_;
  std::optional<MuSeries> mu_;
  double ta_ = 0, tb_ = 0, t_ = 0;  // step [ta, tb]; t the last time returned
  double tstop_ = INFINITY;
  double yend_[6], y_[6];  // state at tb, at t
  SignState state_[kNumRoots];
  int sign_[kNumRoots] = {1, 1, 1};
  bool pending_ = false;      // a root at tb not yet returned
  bool passed_root_ = false;  // the last step passed a root
  int rf_[kNumRoots] = {0, 0, 0};
  long steps_ = 0;
  std::string error_;
};

// Seed eq. (3.5) on one slip branch, x'' = -x - 2 beta x' + sigma mu(s), and
// Phi' = J Phi with J = [0 1; -1 c], c = -2 beta - mu'(s): coefficient k + 1
// from the coefficients up to k.
template <LawKind L, bool Var>
void TaylorStepper::Recurrences(int order) {
  const Model& m = *p_.model;
  const double v = m.v(), two_beta = 2 * m.beta();
  MuSeries& mu = *mu_;
  double* s = s_.c();
  double* cc = cc_.c();
  double* x = c_[0];
  double* xd = c_[1];
  // Zeros in s past the order so far: the sums of products in MuSeries::Old
  // leave out what is new. (c_ and cc only need finite entries there.)
  for (int k = 0; k < order + kPad; ++k) s[k] = 0;
  for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
  mu.Begin<L>(order);
  double damp = 0;  // 2 beta + mu'(s_0)
  for (int k = 0; k < order; ++k) {
    mu.Old<L, Var>(k, s);
    const double inv = kInverse.r[k];
    if (k > 0) {
      // mu_k = alpha + mu'(s_0) s_k with s_k = -sigma x'_k: x'_{k+1} without
      // waiting for the products of s_k (the chain from x'_k is short).
      const double alpha = mu.Alpha<L>(k);
      xd[k + 1] = ((sigma_ * alpha - x[k]) - damp * xd[k]) * inv;
    }
    s[k] = sigma_ * ((k == 0 ? v : 0.0) - xd[k]);
    double dmu = 0;
    const double muk = mu.New<L, Var>(k, s, &dmu);
    x[k + 1] = xd[k] * inv;
    if (k == 0) {
      xd[1] = -x[0] - two_beta * xd[0] + sigma_ * muk;
      damp = two_beta + mu.slope();
    }
    if constexpr (Var) {
      cc[k] = (k == 0 ? -two_beta : 0.0) - dmu;
      for (int col = 2; col < 6; col += 2) {
        const double cq = Cauchy(c_[col + 1], cc, k);
        c_[col][k + 1] = c_[col + 1][k] * inv;
        c_[col + 1][k + 1] = (-c_[col][k] + cq) * inv;
      }
    }
  }
}

void TaylorStepper::Coefficients(int order) {
  const bool var = n_ == 6;
  switch (p_.model->friction().law()) {
    case LawKind::kCubic:
      return var ? Recurrences<LawKind::kCubic, true>(order)
                 : Recurrences<LawKind::kCubic, false>(order);
    case LawKind::kCoulomb:
      return var ? Recurrences<LawKind::kCoulomb, true>(order)
                 : Recurrences<LawKind::kCoulomb, false>(order);
    case LawKind::kStribeck:
      return var ? Recurrences<LawKind::kStribeck, true>(order)
                 : Recurrences<LawKind::kStribeck, false>(order);
    case LawKind::kLeine:
      return var ? Recurrences<LawKind::kLeine, true>(order)
                 : Recurrences<LawKind::kLeine, false>(order);
  }
}

// JZ section 3.2: rho = min over j = p-1, p of (eps / |z_j|)^(1/j), relative to
// |z_0| when rtol |z_0| > atol; h = rho / e^2 exp(-0.7 / (p - 1)). |z_0|
// takes x by SlipProblem::XScale.
double TaylorStepper::StepSize(int order) const {
  auto norm = [&](int k) {
    double m = 0;
    for (int i = 0; i < n_; ++i) m = std::max(m, std::abs(c_[i][k]));
    return m;
  };
  double z0 = p_.XScale(c_[0][0]);
  for (int i = 1; i < n_; ++i) z0 = std::max(z0, std::abs(c_[i][0]));
  const double log_scale = rtol_ * z0 > atol_ ? std::log(z0) : 0.0;
  // min over j of (scale / |z_j|)^(1/j), as logarithms (|z_j| = 0: +inf).
  const double r1 = (log_scale - std::log(norm(order - 1))) / (order - 1);
  const double r2 = (log_scale - std::log(norm(order))) / order;
  return std::exp(std::min(r1, r2) - 2.0 - 0.7 / (order - 1));
}

bool TaylorStepper::NewStep() {
  ta_ = tb_;
  if (tstop_ - ta_ <= 8e-16 * std::max(1.0, std::abs(ta_))) {  // at the stop time to rounding
    order_ = 0;
    for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
    tb_ = tstop_;
    return true;
  }
  double z0 = std::max(p_.XScale(yend_[0]), std::abs(yend_[1]));
  if (n_ == 6)
    for (int i = 2; i < 6; ++i) z0 = std::max(z0, std::abs(yend_[i]));
  order_ = rtol_ * z0 > atol_ ? order_rel_ : order_abs_;
  Coefficients(order_);
  double h = StepSize(order_);
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k <= order_; ++k)
      if (!std::isfinite(c_[i][k])) return Failed("non-finite Taylor coefficients");
  if (std::isnan(h)) return Failed("non-finite step size");
  if (std::isinf(h)) h = 1e3;  // all higher coefficients vanish: at rest exactly
  h = std::min(h, tstop_ - ta_);
  // Underflow: the step no longer moves t (fast fields take tiny steps near
  // t = 0, as CVODE does).
  if (!(h > 0) || ta_ + h == ta_) {
    std::ostringstream os;
    os << "step-size underflow (h = " << h << ")";
    return Failed(os.str());
  }
  ++steps_;
  tb_ = ta_ + h;
  if (tb_ > tstop_) tb_ = tstop_;
  Events(h);
  Evaluate(tb_ - ta_, yend_);
  return true;
}

StepOutcome TaylorStepper::Advance(double tout, double* t) {
  error_.clear();
  long taken = 0;
  for (;;) {
    if (tout <= tb_ && !(pending_ && tout >= tb_)) {  // dense output inside this step
      t_ = std::max(std::min(tout, tb_), t_);
      Evaluate(t_ - ta_, y_);
      *t = t_;
      return StepOutcome::kReached;
    }
    if (pending_) {
      pending_ = false;
      t_ = tb_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kRoot;
    }
    if (tb_ >= tstop_) {
      t_ = tb_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kReached;
    }
    if (taken >= max_steps_) {
      std::ostringstream os;
      os << "too many steps (" << max_steps_ << ") before t = " << tout;
      t_ = tb_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      error_ = os.str();
      return StepOutcome::kTooMuchWork;
    }
    if (!NewStep()) {
      t_ = tb_ = ta_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kFailed;
    }
    // max_steps counts from the last root, passed or returned (as when every
    // root returned, and as CVODE counts between returns).
    taken = passed_root_ ? 0 : taken + 1;
    if (p_.cancel && (*p_.cancel)()) {
      pending_ = false;
      tb_ = ta_;
      Evaluate(0.0, yend_);
      t_ = ta_;
      std::copy(yend_, yend_ + n_, y_);
      *t = t_;
      return StepOutcome::kCancelled;
    }
  }
}

// The roots of g0 = x' - v, g1 = x'', g2 = x' on this step, in u = tau / h.
// The first root that stops (SlipProblem::stop_dir) ends the step there; the
// extrema before it that do not stop are recorded and passed.
void TaylorStepper::Events(double h) {
  const int n = order_;
  double g[kNumRoots][kMaxOrder + 1];
  double hk = 1;
  for (int k = 0; k <= n; ++k, hk *= h) {
    g[0][k] = g[2][k] = c_[1][k] * hk;
    g[1][k] = k < n ? (k + 1) * c_[1][k + 1] * hk : 0.0;
  }
  g[0][0] -= p_.model->v();
  const bool at_rest = p_.AtRest(c_[0][0], c_[1][0], c_[1][1]);
  Roots roots;
  for (int i = 0; i < kNumRoots; ++i) {
    if (i > 0 && at_rest) {  // noise on steady sliding: no events
      state_[i] = kInactive;
      continue;
    }
    if (p_.stop_dir[i] == 0 && (i == 0 || !p_.extrema)) continue;  // not asked for
    EventRoots(i, g[i], i == 1 ? n - 1 : n, roots);
  }
  // The passed extrema before the end of the step; each flips its sign.
  passed_root_ = false;
  for (int j = 0; j < roots.n_passed; ++j) {
    const auto& r = roots.passed[j];
    if (r.u >= roots.first) continue;
    passed_root_ = true;
    sign_[r.i] = -sign_[r.i];
    Extrema& e = *p_.extrema;
    if (r.i == 1) {
      const double xdot = Horner(c_[1], order_, r.u * h);
      e.xdot_min = std::min(e.xdot_min, xdot);
      e.xdot_max = std::max(e.xdot_max, xdot);
    } else {
      const double x = Horner(c_[0], order_, r.u * h);
      e.x_min = std::min(e.x_min, x);
      e.x_max = std::max(e.x_max, x);
    }
  }
  std::copy(roots.rf, roots.rf + kNumRoots, rf_);
  if (roots.first > 1) return;
  pending_ = true;
  for (int i = 0; i < kNumRoots; ++i)
    if (rf_[i] != 0) {
      state_[i] = kDeflate;
      sign_[i] = rf_[i];
    }
  tb_ = roots.first == 1 ? tb_ : ta_ + roots.first * h;
}

// The roots of g_i (degree deg) on (0, 1] in order, up to the first that
// stops or beyond roots.first: passed ones go to roots.passed.
void TaylorStepper::EventRoots(int i, const double* gi, int deg, Roots& roots) {
  // g0: an exact 0 counts as the mode's side; g1, g2: as positive (as the CVODE stepper).
  const int zero_sign = i == 0 && p_.mode == Mode::kSlipBelow ? -1 : 1;
  if (state_[i] == kInactive) state_[i] = kFresh;
  if (state_[i] == kFresh && gi[0] == 0) state_[i] = kDeflate;
  int sign, start_sign;  // g's sign after u = 0; sign_[i] before the passed roots
  if (state_[i] == kDeflate) {
    // A root at the step start (a start on the surface, or the root just
    // returned) is not an event: g / u from there on.
    while (deg > 0 && gi[1] == 0) ++gi, --deg;
    if (deg == 0) return;  // g vanishes identically
    ++gi, --deg;
    sign = start_sign = gi[0] > 0 ? 1 : -1;
  } else {
    sign = start_sign = gi[0] > 0 ? 1 : (gi[0] < 0 ? -1 : zero_sign);
    if (state_[i] == kTracked && sign != sign_[i]) {
      // Changed sign across the step boundary (the two step polynomials
      // disagree within truncation): a root at the step start.
      if (roots.Add(i, 0.0, sign, p_.Stops(i, sign))) return;
      start_sign = -sign;  // passed: its flip comes with the others
    }
  }
  sign_[i] = start_sign;
  state_[i] = kTracked;
  const double* poly = gi;
  int d = deg;
  double tail[kMaxOrder + 1];
  double u0 = 0;
  for (int guard = 0; guard <= 2 * deg + 2; ++guard) {
    const PolyRoot r = FirstSignChange(poly, d, sign, zero_sign);
    if (!r.found) return;
    const double u = r.u == 1 ? 1.0 : u0 + (1 - u0) * r.u;
    if (u > roots.first || roots.Add(i, u, -sign, p_.Stops(i, -sign)) || u >= 1) return;
    // Passed: go on from u with g / (w - u) (the root is not an event twice).
    sign = -sign;
    RestrictToTail(gi, deg, u, tail);
    poly = tail;
    d = deg;
    while (d > 0 && poly[1] == 0) ++poly, --d;
    if (d == 0) return;
    ++poly, --d;
    if ((poly[0] > 0 ? 1 : -1) != sign) return;  // a touch, not a crossing: rounding
    u0 = u;
  }
}

}  // namespace

std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational) {
  return std::make_unique<TaylorStepper>(options, variational);
}

}  // namespace stickslip
