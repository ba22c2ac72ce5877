// The Taylor stepper for one slip mode: coefficients of z (and Phi) by
// recurrences, order and step from the tolerance (Jorba & Zou 2005, Exp. Math.
// 14, section 3.2, with heyoka's safety factor, Biscani & Izzo 2021, eq. 10),
// events as the first sign changes of the step polynomials (poly_roots.hpp);
// the step polynomial is the dense output.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "poly_roots.hpp"
#include "stepper.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/parameter_axis.hpp"

namespace stickslip {
namespace {

constexpr int kMaxOrder = 36;

// JZ (3.8): order p = ceil(-ln(eps) / 2 + 1).
int OrderFor(double eps) {
  return std::min(kMaxOrder, static_cast<int>(std::ceil(-0.5 * std::log(eps) + 1.0)));
}

class TaylorStepper final : public Stepper {
 public:
  TaylorStepper(const FlowOptions& o, bool variational, const std::string& parameter)
      : rtol_(o.rtol),
        atol_(o.atol),
        max_steps_(o.max_steps),
        n_(!parameter.empty() ? 8
           : variational      ? 6
                              : 2),
        order_rel_(OrderFor(o.rtol)),
        order_abs_(OrderFor(o.atol)),
        parameter_(parameter) {}

  void Reset(const SlipProblem& problem, double t0, const double* y0) override {
    p_ = problem;
    sigma_ = p_.mode == Mode::kSlipBelow ? 1 : -1;
    if (n_ == 8) ResolveParameter();
    std::copy(y0, y0 + n_, yend_);
    std::copy(y0, y0 + n_, y_);
    ta_ = tb_ = t_ = t0;
    tstop_ = INFINITY;
    steps_ = 0;
    pending_ = false;
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

  bool NewStep();
  void ResolveParameter();
  void Coefficients(int order);
  double ParamTerm(int k, const double* s, double muk, double dmu,
                   std::optional<MuSeries>& shifted) const;
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
  int sigma_ = 1;                   // F = sigma mu(s), s = sigma (v - x')
  double c_[8][kMaxOrder + 1];      // this step's Taylor coefficients
  double ta_ = 0, tb_ = 0, t_ = 0;  // step [ta, tb]; t the last time returned
  double tstop_ = INFINITY;
  double yend_[8], y_[8];  // state at tb, at t
  SignState state_[kNumRoots];
  int sign_[kNumRoots] = {1, 1, 1};
  bool pending_ = false;  // a root at tb not yet returned
  int rf_[kNumRoots] = {0, 0, 0};
  long steps_ = 0;
  std::string error_;
  // The parameter column dz/dp (entries 6, 7): which term df/dp carries.
  enum class ParamKind { kBeta, kV, kAffine };
  std::string parameter_;
  ParamKind kind_ = ParamKind::kBeta;
  std::optional<Friction> shifted_;  // kAffine: the law at p + dp_
  double dp_ = 1;
};

// df/dp of seed eq. (3.5) for the parameter column: beta gives (0, -2 x');
// v enters through s = sigma (v - x') only, giving (0, mu'(s)); a law
// parameter mu depends on affinely (mu_s, mu_m, mu_k, k5) gives
// (0, sigma (mu(s; p + dp) - mu(s; p)) / dp), exact for any dp. v_m, v_s and
// delta enter mu non-affinely: no column (InvalidArgument).
void TaylorStepper::ResolveParameter() {
  const ParameterAxis axis(parameter_);
  const Params& q = p_.model->params();
  if (!ParameterColumnSupported(q.law, parameter_))
    throw InvalidArgument("parameter column: '" + parameter_ +
                          "' enters the friction law non-affinely (not supported)");
  shifted_.reset();
  if (parameter_ == "beta") {
    kind_ = ParamKind::kBeta;
  } else if (parameter_ == "v") {
    kind_ = ParamKind::kV;
  } else {
    kind_ = ParamKind::kAffine;
    dp_ = std::max(1.0, std::abs(axis.Get(q)));
    shifted_.emplace(axis.At(q, axis.Get(q) + dp_));
  }
}

// Seed eq. (3.5) on one slip branch, x'' = -x - 2 beta x' + sigma mu(s), and
// Phi' = J Phi with J = [0 1; -1 c], c = -2 beta - mu'(s), and the parameter
// column z_p' = J z_p + df/dp: coefficient k + 1 from those up to k.
void TaylorStepper::Coefficients(int order) {
  const Model& m = *p_.model;
  const double v = m.v(), two_beta = 2 * m.beta();
  MuSeries mu(m.friction());
  std::optional<MuSeries> mu_shifted;
  if (shifted_) mu_shifted.emplace(*shifted_);
  const bool var = n_ >= 6;
  double s[kMaxOrder + 1], cc[kMaxOrder + 1];
  for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
  for (int k = 0; k < order; ++k) {
    s[k] = sigma_ * ((k == 0 ? v : 0.0) - c_[1][k]);
    double dmu = 0;
    const double muk = mu.Next(k, s, var ? &dmu : nullptr);
    const double inv = 1.0 / (k + 1);
    c_[0][k + 1] = c_[1][k] * inv;
    c_[1][k + 1] = (-c_[0][k] - two_beta * c_[1][k] + sigma_ * muk) * inv;
    if (!var) continue;
    cc[k] = (k == 0 ? -two_beta : 0.0) - dmu;
    for (int col = 2; col < n_; col += 2) {
      double cq = 0;
      for (int j = 0; j <= k; ++j) cq += cc[j] * c_[col + 1][k - j];
      c_[col][k + 1] = c_[col + 1][k] * inv;
      c_[col + 1][k + 1] = (-c_[col][k] + cq) * inv;
    }
    if (n_ == 8) c_[7][k + 1] += ParamTerm(k, s, muk, dmu, mu_shifted) * inv;
  }
}

// Coefficient k of df_2/dp (ResolveParameter), from this step's series.
double TaylorStepper::ParamTerm(int k, const double* s, double muk, double dmu,
                                std::optional<MuSeries>& shifted) const {
  switch (kind_) {
    case ParamKind::kBeta:
      return -2 * c_[1][k];
    case ParamKind::kV:
      return dmu;
    case ParamKind::kAffine:
      return sigma_ * (shifted->Next(k, s, nullptr) - muk) / dp_;
  }
  return 0;
}

// JZ section 3.2: rho = min over j = p-1, p of (eps / |z_j|)^(1/j), relative to
// |z_0| when rtol |z_0| > atol; h = rho / e^2 exp(-0.7 / (p - 1)).
double TaylorStepper::StepSize(int order) const {
  auto norm = [&](int k) {
    double m = 0;
    for (int i = 0; i < n_; ++i) m = std::max(m, std::abs(c_[i][k]));
    return m;
  };
  const double z0 = norm(0);
  const double scale = rtol_ * z0 > atol_ ? z0 : 1.0;
  const double r1 = std::pow(scale / norm(order - 1), 1.0 / (order - 1));
  const double r2 = std::pow(scale / norm(order), 1.0 / order);
  return std::min(r1, r2) * std::exp(-2.0 - 0.7 / (order - 1));
}

bool TaylorStepper::NewStep() {
  ta_ = tb_;
  if (tstop_ - ta_ <= 8e-16 * std::max(1.0, std::abs(ta_))) {  // at the stop time to rounding
    order_ = 0;
    for (int i = 0; i < n_; ++i) c_[i][0] = yend_[i];
    tb_ = tstop_;
    return true;
  }
  double z0 = std::max(std::abs(yend_[0]), std::abs(yend_[1]));
  if (n_ >= 6)
    for (int i = 2; i < n_; ++i) z0 = std::max(z0, std::abs(yend_[i]));
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
    ++taken;
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
void TaylorStepper::Events(double h) {
  const int n = order_;
  double g[kNumRoots][kMaxOrder + 1];
  double hk = 1;
  for (int k = 0; k <= n; ++k, hk *= h) {
    g[0][k] = g[2][k] = c_[1][k] * hk;
    g[1][k] = k < n ? (k + 1) * c_[1][k + 1] * hk : 0.0;
  }
  g[0][0] -= p_.model->v();
  // g0: an exact 0 counts as the mode's side; g1, g2: as positive (as the CVODE stepper).
  const int zero_sign[kNumRoots] = {p_.mode == Mode::kSlipBelow ? -1 : 1, 1, 1};
  const bool at_rest = p_.AtRest(c_[0][0], c_[1][0], c_[1][1]);
  double first = 2;
  int rf[kNumRoots] = {0, 0, 0};
  for (int i = 0; i < kNumRoots; ++i) {
    if (i > 0 && at_rest) {  // noise on steady sliding: no events
      state_[i] = kInactive;
      continue;
    }
    const double* gi = g[i];
    int deg = i == 1 ? n - 1 : n;
    if (state_[i] == kInactive) state_[i] = kFresh;
    if (state_[i] == kFresh && gi[0] == 0) state_[i] = kDeflate;
    if (state_[i] == kDeflate) {
      // A root at the step start (a start on the surface, or the root just
      // returned) is not an event: g / u from there on.
      while (deg > 0 && gi[1] == 0) ++gi, --deg;
      if (deg == 0) continue;  // g vanishes identically
      ++gi, --deg;
      sign_[i] = gi[0] > 0 ? 1 : -1;
    } else {
      const int s = gi[0] > 0 ? 1 : (gi[0] < 0 ? -1 : zero_sign[i]);
      if (state_[i] == kTracked && s != sign_[i]) {
        // Changed sign across the step boundary (the two step polynomials
        // disagree within truncation): a root at the step start.
        if (first > 0) std::fill(rf, rf + kNumRoots, 0);
        first = 0;
        rf[i] = s;
        continue;
      }
      sign_[i] = s;
    }
    state_[i] = kTracked;
    const PolyRoot r = FirstSignChange(gi, deg, sign_[i], zero_sign[i]);
    if (!r.found || r.u > first) continue;
    if (r.u < first) std::fill(rf, rf + kNumRoots, 0);
    first = r.u;
    rf[i] = -sign_[i];
  }
  std::copy(rf, rf + kNumRoots, rf_);
  if (first > 1) return;
  pending_ = true;
  for (int i = 0; i < kNumRoots; ++i)
    if (rf_[i] != 0) {
      state_[i] = kDeflate;
      sign_[i] = rf_[i];
    }
  tb_ = first == 1 ? tb_ : ta_ + first * h;
}

}  // namespace

std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational,
                                           const std::string& parameter) {
  return std::make_unique<TaylorStepper>(options, variational, parameter);
}

}  // namespace stickslip
