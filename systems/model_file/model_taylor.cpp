// A model file's Taylor recurrences (taylor_field.hpp): its mode's tape run
// order by order (tape.hpp). With coefficients 0..k of the state, the
// tape's order k gives f_k, so z_{k+1} = f_k / (k+1); the variational rows
// take J's series: Phi_{k+1} = sum_{j=0..k} J_j Phi_{k-j} / (k+1); the
// auxiliary rows are the sticking contacts' lambda and static limit.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "model_file/model_file.hpp"
#include "model_file/model_system.hpp"

namespace stickslip::model_file {

namespace {

class ModelField final : public TaylorField {
  static constexpr int kExtraOrder = 6;

 public:
  bool Bind(const System& s, const ModeSet& m) override {
    const auto* o = dynamic_cast<const ModelSystem*>(&s);
    if (!o) return false;
    program_ = &o->Program(m);
    params_ = o->values();
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
  void Entries(const Tape& tape, int n);

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
  const bool var = l.variational;
  const Tape& tape = var ? p.full : p.plain;
  const std::vector<int>& field = var ? p.full_field : p.field;
  const std::vector<int>& aux = var ? p.full_aux : p.aux;
  if (capacity_ < tape.size()) {
    rows_ = std::make_unique<TaylorRow[]>(tape.size());
    capacity_ = tape.size();
    prepared_ = nullptr;
  }
  if (prepared_ != &tape) {
    tape.Constants(params_.data(), rows_.get());
    prepared_ = &tape;
    if (var) Entries(tape, l.tangent);
  }
  for (int k = 0; k <= order; ++k) {
    tape.Order(k, c, rows_.get());
    if (k == order) break;
    const double inv = 1.0 / (k + 1);
    for (int t = 0; t < l.n; ++t) c[t][k + 1] = rows_[field[t]][k] * inv;
    if (var) Phi(k, l, c);
  }
  for (int q = 0; q < aux_; ++q) {
    double* row = c[l.aux_first() + q];
    std::fill(row, row + kTaylorRowSize, 0.0);  // entries past order stay finite
    for (int k = 0; k <= order; ++k) row[k] = rows_[aux[q]][k];
  }
}

// Coefficient k+1 of Phi = dz/dz0 (column-major) from J's series 0..k; a
// constant entry of J is one product, a zero one none.
void ModelField::Phi(int k, const TaylorLayout& l, TaylorRow* c) const {
  const int n = l.tangent;
  const double inv = 1.0 / (k + 1);
  for (int col = 0; col < n; ++col) {
    const int base = l.phi() + col * n;
    for (int r = 0; r < n; ++r) {
      double s = 0;
      for (const Entry& e : entries_[r]) {
        const double* q = c[base + e.u];
        if (e.constant) {
          s += e.value * q[k];
        } else {
          const double* J = rows_[e.node];
          for (int j = 0; j <= k; ++j) s += J[j] * q[k - j];
        }
      }
      c[base + r][k + 1] = s * inv;
    }
  }
}

// J's nonzero entries per row, after the constant rows are in place.
void ModelField::Entries(const Tape& tape, int n) {
  entries_.assign(n, {});
  const std::vector<int>& jac = program_->jacobian;
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

std::unique_ptr<TaylorField> ModelSystem::MakeTaylorField(const TaylorRequest&) const {
  // No parameter column (SupportsParameterColumn stays false): the branch
  // driver takes dF/dp by differences.
  return std::make_unique<ModelField>();
}

}  // namespace stickslip::model_file
