// A model file's Taylor recurrences (taylor_field.hpp): its mode's tape run
// order by order (tape.hpp). With coefficients 0..k of the state, the
// tape's order k gives f_k, so z_{k+1} = f_k / (k+1); the variational rows
// take J's series: Phi_{k+1} = sum_{j=0..k} J_j Phi_{k-j} / (k+1); the
// parameter column z_p' = J z_p + (df/dtheta) theta_p + df/dp likewise (the
// tape of that parameter, compiled.hpp); the auxiliary rows are the sticking
// contacts' lambda and static limit.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "common/law_series.hpp"
#include "model_file/model_file.hpp"
#include "model_file/model_system.hpp"

namespace stickslip::model_file {

namespace {

class ModelField final : public TaylorField {
  static constexpr int kExtraOrder = 6;

 public:
  explicit ModelField(std::optional<int> parameter) : parameter_(parameter) {}
  bool Bind(const System& s, const ModeSet& m) override {
    const auto* o = dynamic_cast<const ModelSystem*>(&s);
    if (!o) return false;
    model_ = o;
    params_ = o->values();
    return BindMode(m);
  }
  bool BindMode(const ModeSet& m) override {
    program_ = &model_->Program(m);
    aux_ = 2 * m.Sticking();
    prepared_ = nullptr;  // the constant rows are the new mode's, at these parameters
    return true;
  }
  int AuxRows() const override { return aux_; }
  void Coefficients(int order, const TaylorLayout& l, TaylorRow* c) override;
  // Six orders above Jorba & Zou's, as the built-in cubic fields: the seed
  // orbit 24.6 -> 21.0 us, its branch 392 -> 322 ms (bench/model_file_bench).
  int ExtraOrder(double /*eps*/, bool /*in_steps*/) const override { return kExtraOrder; }

 private:
  struct Entry {
    int u, node;
    bool constant;
    double value;
  };
  void Phi(int k, const TaylorLayout& l, TaylorRow* c) const;
  void Column(int k, const TaylorLayout& l, TaylorRow* c) const;
  void Entries(const Tape& tape, const std::vector<int>& jacobian, int n);
  void Cauchy(const Entry& e, const double* q, int k, double* s) const;

  std::optional<int> parameter_;        // the column's, if the runs ask for one
  const ModelSystem* model_ = nullptr;  // the bound system
  const ModeProgram* program_ = nullptr;
  std::vector<double> params_;
  int aux_ = 0;
  std::vector<std::vector<Entry>> entries_;  // J's nonzero entries per row (full tape)
  const Tape* prepared_ = nullptr;           // the tape whose constant rows rows_ holds
  std::unique_ptr<TaylorRow[]> rows_;        // one row per tape node
  int capacity_ = 0;
};

void ModelField::Coefficients(int order, const TaylorLayout& l, TaylorRow* c) {
  const ModeProgram& p = *program_;
  if (!p.consistent) {  // a singular stick set: the stepper reports non-finite coefficients
    for (int r = 0; r < l.rows(); ++r) std::fill(c[r] + 1, c[r] + kTaylorRowSize, NAN);
    return;
  }
  const bool var = l.variational, col = l.column && parameter_;
  const Tape& tape = col ? p.column[*parameter_] : var ? p.full : p.plain;
  const std::vector<int>& field = var || col ? p.full_field : p.field;
  const std::vector<int>& aux = var || col ? p.full_aux : p.aux;
  if (capacity_ < tape.size()) {
    rows_ = std::make_unique<TaylorRow[]>(tape.size());
    capacity_ = tape.size();
    prepared_ = nullptr;
  }
  if (prepared_ != &tape) {
    tape.Constants(params_.data(), rows_.get());
    prepared_ = &tape;
    if (var || col) Entries(tape, p.jacobian, l.tangent);
  }
  for (int k = 0; k <= order; ++k) {
    tape.Order(k, c, rows_.get());
    if (k == order) break;
    const double inv = 1.0 / (k + 1);
    for (int t = 0; t < l.n; ++t) c[t][k + 1] = rows_[field[t]][k] * inv;
    if (var) Phi(k, l, c);
    if (col) Column(k, l, c);
  }
  for (int q = 0; q < aux_; ++q) {
    double* row = c[l.aux_first() + q];
    std::fill(row, row + kTaylorRowSize, 0.0);  // entries past order stay finite
    for (int k = 0; k <= order; ++k) row[k] = rows_[aux[q]][k];
  }
}

// s += coefficient k of J_e q (a Cauchy product; a constant entry is one
// product, a zero one none).
void ModelField::Cauchy(const Entry& e, const double* q, int k, double* s) const {
  if (e.constant) {
    *s += e.value * q[k];
    return;
  }
  *s += systems::Cauchy(rows_[e.node], q, k);
}

// Coefficient k+1 of Phi = dz/dz0 (column-major) from J's series 0..k.
void ModelField::Phi(int k, const TaylorLayout& l, TaylorRow* c) const {
  const int n = l.tangent;
  const double inv = 1.0 / (k + 1);
  for (int col = 0; col < n; ++col) {
    const int base = l.phi() + col * n;
    for (int r = 0; r < n; ++r) {
      double s = 0;
      for (const Entry& e : entries_[r]) Cauchy(e, c[base + e.u], k, &s);
      c[base + r][k + 1] = s * inv;
    }
  }
}

// Coefficient k+1 of the column z_p (all n rows): J z_p on the tangent
// block, plus df/dtheta theta_p with a clock, plus df/dp; a clock's row has
// the rate d omega / dp (a constant), so theta_p = (t - t0) d omega / dp.
void ModelField::Column(int k, const TaylorLayout& l, TaylorRow* c) const {
  const ModeProgram& p = *program_;
  const int nt = l.tangent, j = *parameter_;
  const double inv = 1.0 / (k + 1);
  const int base = l.param();
  for (int r = 0; r < l.n; ++r) {
    double s = rows_[p.dfield[j][r]][k];
    if (r < nt) {
      for (const Entry& e : entries_[r]) Cauchy(e, c[base + e.u], k, &s);
      if (!p.dclock.empty()) {
        const double* g = rows_[p.dclock[r]];
        const double* th = c[base + nt];
        for (int i = 0; i <= k; ++i) s += g[i] * th[k - i];
      }
    }
    c[base + r][k + 1] = s * inv;
  }
}

// J's nonzero entries per row, after the constant rows are in place.
void ModelField::Entries(const Tape& tape, const std::vector<int>& jac, int n) {
  entries_.assign(n, {});
  for (int r = 0; r < n; ++r)
    for (int u = 0; u < n; ++u) {
      const int node = jac[r * n + u];
      const bool constant = tape.constant(node);
      const double value = rows_[node][0];
      if (constant && value == 0) continue;
      entries_[r].push_back({u, node, constant, value});
    }
}

}  // namespace

std::unique_ptr<TaylorField> ModelSystem::MakeTaylorField(const TaylorRequest& request) const {
  return std::make_unique<ModelField>(request.parameter);
}

}  // namespace stickslip::model_file
