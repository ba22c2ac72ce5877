// A model file's system (model_system.hpp).
#include "model_file/model_system.hpp"

#include <cmath>

#include "model_file/model_file.hpp"
#include "model_file/model_spec.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::model_file {

namespace {

int ModeIndex(const ModeSet& m, int k) {
  int index = 0;
  for (int c = k - 1; c >= 0; --c) index = 3 * index + static_cast<int>(m[c]);
  return index;
}

// The linear form of the contact tape's values.
ContactVelocity Form(const LinearForm& f, const std::vector<double>& v) {
  ContactVelocity out;
  for (std::size_t t = 0; t < f.weight.size(); ++t)
    if (f.weight[t] >= 0 && out.size < ContactVelocity::kMaxTerms)
      out.terms[out.size++] = {static_cast<int>(t), v[f.weight[t]]};
  out.speed = v[f.speed];
  return out;
}

}  // namespace

ModelSystem::ModelSystem(std::shared_ptr<const Compiled> c) : c_(std::move(c)), p_(c_->defaults) {
  Update();
}

void ModelSystem::Update() {
  contact_values_.resize(c_->contact.size());
  const std::vector<double> zero(c_->n, 0.0);
  c_->contact.Values(zero.data(), p_.data(), contact_values_.data());
  velocity_.clear(), normal_.clear(), static_.clear();
  for (int i = 0; i < c_->k; ++i) {
    velocity_.push_back(Form(c_->velocity[i], contact_values_));
    normal_.push_back(Form(c_->normal[i], contact_values_));
    static_.push_back(contact_values_[c_->static_coefficient[i]]);
  }
}

bool ModelSystem::Assign(const System& s) {
  const auto* o = dynamic_cast<const ModelSystem*>(&s);
  if (!o || o->c_ != c_) return false;
  p_ = o->p_, velocity_ = o->velocity_, normal_ = o->normal_, static_ = o->static_;
  contact_values_ = o->contact_values_;
  return true;
}

std::string ModelSystem::ValidationError() const {
  for (int j = 0; j < parameters(); ++j)
    if (!std::isfinite(p_[j])) return c_->parameters[j] + " must be finite";
  for (const Denominator& d : c_->denominators)
    if (!(contact_values_[d.node] != 0) || !std::isfinite(contact_values_[d.node]))
      return UnmangleRates(d.text) + " = " + Number(contact_values_[d.node]) + " divides (" +
             c_->source + ":" + std::to_string(d.line) + ")";
  if (c_->clocks) {
    const double rate = contact_values_[c_->clock_rate.node];
    if (!(rate > 0) || !std::isfinite(rate))
      return "the clock's rate " + c_->clock_rate.text + " = " + Number(rate) + " (" + c_->source +
             ":" + std::to_string(c_->clock_rate.line) + ") must be > 0";
  }
  for (int i = 0; i < c_->k; ++i)
    if (!c_->normal_varies[i] && !(-normal_[i].speed > 0 && std::isfinite(normal_[i].speed)))
      return "the normal force of contact " + c_->contact_names[i] + " is " +
             Number(normal_[i].speed == 0 ? 0.0 : -normal_[i].speed) +
             ": a constant normal force must be > 0";
  for (int i = 0; i < c_->k; ++i)
    if (!(static_[i] > 0) || !std::isfinite(static_[i]))
      return "the static coefficient of contact " + c_->contact_names[i] + " is " +
             Number(static_[i]) + " (" + c_->source + ":" + std::to_string(c_->static_lines[i]) +
             "): it must be > 0";
  return "";
}

void ModelSystem::SetParameterValue(int j, double value) {
  p_[j] = value;
  Update();
}

std::string ModelSystem::ParameterError(int j) const {
  if (j < 0 || j >= parameters() || c_->parameter_used[j]) return "";
  return "parameter '" + c_->parameters[j] + "' appears in no expression of " + c_->source +
         " (a branch in it would be flat)";
}

std::optional<ContactVelocity> ModelSystem::NormalForce(int i) const {
  if (!c_->normal_varies[i]) return std::nullopt;
  return normal_[i];
}

double ModelSystem::StaticLimit(int i, ConstState z) const {
  return static_[i] * normal_[i].At(z.data());
}

void ModelSystem::StaticLimitGradient(int i, ConstState, StateOut g) const {
  g.setZero();
  for (int t = 0; t < normal_[i].size; ++t)
    g[normal_[i].terms[t].index] = static_[i] * normal_[i].terms[t].weight;
}

const ModeProgram& ModelSystem::Program(const ModeSet& m) const {
  return c_->modes[ModeIndex(m, c_->k)];
}

void ModelSystem::Values(const Tape& t, ConstState z, std::vector<double>& out) const {
  out.resize(t.size());
  t.Values(z.data(), p_.data(), out.data());
}

void ModelSystem::Field(const ModeSet& m, ConstState z, StateOut f) const {
  const ModeProgram& p = Program(m);
  if (!p.consistent) return f.setConstant(NAN), void();  // a singular stick set: no field
  thread_local std::vector<double> v;
  Values(p.plain, z, v);
  for (int t = 0; t < c_->n; ++t) f[t] = v[p.field[t]];
}

void ModelSystem::Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const {
  const ModeProgram& p = Program(m);
  if (!p.consistent) return J.setConstant(NAN), void();
  thread_local std::vector<double> v;
  Values(p.full, z, v);
  const int nt = tangent_dimension();
  for (int r = 0; r < nt; ++r)
    for (int u = 0; u < nt; ++u) J(r, u) = v[p.jacobian[r * nt + u]];
}

// Contact i's place among the sticking contacts of m.
static int StickSlot(const ModeSet& m, int i) {
  int q = 0;
  for (int c = 0; c < i; ++c) q += m.sticks(c);
  return q;
}

double ModelSystem::StickForce(const ModeSet& m, int i, ConstState z) const {
  const ModeProgram& p = Program(m);
  if (!p.consistent) return NAN;  // never within a static limit: the set is not chosen
  thread_local std::vector<double> v;
  Values(p.plain, z, v);
  return v[p.aux[2 * StickSlot(m, i)]];
}

void ModelSystem::StickForceGradient(const ModeSet& m, int i, ConstState z, StateOut g) const {
  const ModeProgram& p = Program(m);
  if (!p.consistent) return g.setConstant(NAN), void();
  thread_local std::vector<double> v;
  Values(p.full, z, v);
  const std::vector<int>& grad = p.lambda_gradient[StickSlot(m, i)];
  for (int u = 0; u < c_->n; ++u) g[u] = v[grad[u]];
}

ContactSensitivity ModelSystem::ContactParameterDerivative(const ModeSet& m, int i, int j,
                                                           ConstState z) const {
  ContactSensitivity d;
  thread_local std::vector<double> v;
  Values(c_->contact, z, v);
  d.speed = -v[c_->dvelocity[i][j]];  // -dh/dp at z (h = w.z - speed; w may read p too)
  const ModeProgram& p = Program(m);
  if (!p.consistent || !m.sticks(i)) return d;
  Values(p.column[j], z, v);
  const int q = StickSlot(m, i);
  d.stick_force = v[p.daux[j][2 * q]];
  d.static_limit = v[p.daux[j][2 * q + 1]];
  return d;
}

double ModelSystem::ClockRateDerivative(int, int j) const {
  return c_->clocks ? contact_values_[c_->dclock_rate[j]] : 0.0;
}

// Newton on f(x) = 0 from x; true if it converged to a finite point.
bool ModelSystem::Newton(const ModeSet& m, Eigen::VectorXd& x) const {
  Eigen::VectorXd f(c_->n);
  Eigen::MatrixXd J(c_->n, c_->n);
  for (int it = 0; it < 50; ++it) {
    Field(m, x, f);
    Jacobian(m, x, J);
    const Eigen::VectorXd dx = J.fullPivLu().solve(-f);
    if (!dx.allFinite()) return false;
    x += dx;
    if (dx.lpNorm<Eigen::Infinity>() <= 1e-14 * (1 + x.lpNorm<Eigen::Infinity>())) break;
  }
  Field(m, x, f);
  return x.allFinite() && f.lpNorm<Eigen::Infinity>() <= 1e-10 * (1 + x.lpNorm<Eigen::Infinity>());
}

// The speed of sliding at x: the sum of the contacts' |h|.
double ModelSystem::Sliding(const Eigen::VectorXd& x) const {
  double sum = 0;
  for (int c = 0; c < c_->k; ++c) sum += std::abs(velocity_[c].At(x.data()));
  return sum;
}

// Newton from the guess z, if any (the rest point there if on the mode's
// side of every contact, else none: a branch stops rather than jump to
// another rest point); else from the state 0 and from states that put every
// contact's velocity on the mode's side at 0.01 ... 100 (a Stribeck law's
// field may lead Newton from 0 to the root on the other side, and a drill's
// steady rotations come in pairs): the first stable one, else the fastest
// sliding (the drill's fast rotation, unstable below its Hopf point).
bool ModelSystem::Rest(const ModeSet& m, StateOut z, bool* stable) const {
  if (m.AnySticks() || c_->clocks) return false;  // a forcing has no rest point
  bool found = false;
  Eigen::MatrixXd J(c_->n, c_->n);
  const Eigen::VectorXd guess = z;
  const bool near = guess.allFinite() && guess.any();
  for (int start = near ? -1 : 0; start <= 5; ++start) {
    Eigen::VectorXd x = start < 0 ? guess : Eigen::VectorXd::Zero(c_->n);
    for (int c = 0; start > 0 && c < c_->k; ++c) {
      const ContactVelocity& h = velocity_[c];
      double norm = 0;
      for (int t = 0; t < h.size; ++t) norm += h.terms[t].weight * h.terms[t].weight;
      const double side = m[c] == Mode::kSlipAbove ? 1 : -1;
      const double shift = (side * std::pow(10.0, start - 3) - h.At(x.data())) / norm;
      for (int t = 0; t < h.size; ++t) x[h.terms[t].index] += shift * h.terms[t].weight;
    }
    bool side = Newton(m, x);
    for (int c = 0; side && c < c_->k; ++c) {
      const double h = velocity_[c].At(x.data());
      side = (m[c] == Mode::kSlipBelow && h < 0) || (m[c] == Mode::kSlipAbove && h > 0);
    }
    if (!side) {
      if (start < 0) return false;
      continue;
    }
    Jacobian(m, x, J);
    const bool here = J.eigenvalues().real().maxCoeff() < 0;
    if (!found || here || Sliding(x) > Sliding(z)) z = x, *stable = here;
    found = true;
    if (here || start < 0) break;
  }
  return found;
}

std::string ModelName(const System& s) {
  const auto* m = dynamic_cast<const ModelSystem*>(&s);
  return m ? m->compiled().name : std::string();
}

}  // namespace stickslip::model_file
