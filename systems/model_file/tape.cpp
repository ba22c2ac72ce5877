// The tape's recurrences (tape.hpp; Jorba & Zou 2005, section 3.1;
// Griewank & Walther 2008, ch. 13).
#include "model_file/tape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/law_series.hpp"

namespace stickslip::model_file {

int Tape::Add(const Node& n) {
  bool c = n.op == Op::kParam || n.op == Op::kConst;
  if (n.op != Op::kState && !c) {
    const bool binary =
        n.op == Op::kAdd || n.op == Op::kSub || n.op == Op::kMul || n.op == Op::kDiv;
    c = constant_[n.a] && (!binary || constant_[n.b]);
  }
  nodes_.push_back(n);
  constant_.push_back(c);
  return size() - 1;
}

namespace {

// sum_{j=1..k} j u_j w_{k-j}, in two partial sums (common/law_series.hpp)
double Weighted(int k, const double* u, const double* w) {
  double s0 = 0, s1 = 0;
  int j = 1;
  for (; j + 1 <= k; j += 2) s0 += j * u[j] * w[k - j], s1 += (j + 1) * u[j + 1] * w[k - j - 1];
  if (j <= k) s0 += j * u[j] * w[k - j];
  return s0 + s1;
}

// sum_{j=lo..k} u_j w_{k-j}
double Cauchy(int lo, int k, const double* u, const double* w) {
  return systems::Cauchy(u + lo, w, k - lo);
}

}  // namespace

// Node i as base * factor with a constant factor (a new constant node for
// 1 / c or -c): a product or quotient by a constant, or a negation.
bool Tape::Scale(int i, int* base, int* factor) {
  const Node n = nodes_[i];
  if (constant_[i]) return false;
  if (n.op == Op::kMul && (constant_[n.a] || constant_[n.b])) {
    *base = constant_[n.a] ? n.b : n.a, *factor = constant_[n.a] ? n.a : n.b;
    return true;
  }
  if (n.op == Op::kDiv && constant_[n.b]) {
    *base = n.a, *factor = Add({Op::kDiv, Add({Op::kConst, 0, 0, 1.0}), n.b, 0});
    return true;
  }
  if (n.op == Op::kNeg) {
    *base = n.a, *factor = Add({Op::kConst, 0, 0, -1.0});
    return true;
  }
  return false;
}

// (k f) g -> k (f g): a chain of scalings costs one product per order.
void Tape::Fold() {
  const int n = size();
  for (int i = 0; i < n; ++i) {
    int base = 0, factor = 0, inner_base = 0, inner_factor = 0;
    if (!Scale(i, &base, &factor) || !Scale(base, &inner_base, &inner_factor)) continue;
    const int product = Add({Op::kMul, inner_factor, factor, 0});
    nodes_[i] = {Op::kMul, inner_base, product, 0};
  }
}

// Every node an output reads, by a worklist: Fold's products come after
// the nodes that read them.
std::vector<bool> Tape::Reads(const std::vector<int>& outputs) const {
  std::vector<bool> live(size(), false);
  std::vector<int> todo;
  auto mark = [&](int i) {
    if (!live[i]) live[i] = true, todo.push_back(i);
  };
  for (int o : outputs) mark(o);
  while (!todo.empty()) {
    const Node& n = nodes_[todo.back()];
    todo.pop_back();
    if (n.op == Op::kState || n.op == Op::kParam || n.op == Op::kConst) continue;
    mark(n.a);
    const bool binary = n.op == Op::kAdd || n.op == Op::kSub || n.op == Op::kMul ||
                        n.op == Op::kDiv || n.op == Op::kSin || n.op == Op::kCos ||
                        n.op == Op::kSinh || n.op == Op::kCosh;  // a pair reads its partner
    if (binary) mark(n.b);
  }
  return live;
}

void Tape::Seal(const std::vector<int>& outputs) {
  Fold();
  const std::vector<bool> live = Reads(outputs);
  live_ = live;
  program_.clear();
  for (int i = 0; i < size(); ++i) {
    if (constant_[i] || !live[i]) continue;
    const Node& n = nodes_[i];
    Instr in{Step::kOther, i, n.a, n.b};
    switch (n.op) {
      case Op::kState:
        in.step = Step::kState;
        break;
      case Op::kAdd:
        in.step = Step::kAdd;
        break;
      case Op::kSub:
        in.step = Step::kSub;
        break;
      case Op::kNeg:
        in.step = Step::kNeg;
        break;
      case Op::kMul:
        in.step = constant_[n.a] || constant_[n.b] ? Step::kScale : Step::kMul;
        if (constant_[n.a]) std::swap(in.a, in.b);  // kScale: a varies, b is constant
        break;
      case Op::kDiv:
        in.step = constant_[n.b] ? Step::kDivConst : Step::kDiv;
        break;
      default:
        break;
    }
    program_.push_back(in);
  }
}

void Tape::Order(int k, const TaylorRow* state, TaylorRow* rows) const {
  for (const Instr& in : program_) {
    double* r = rows[in.node];
    const double* u = rows[in.a];
    const double* w = rows[in.b];
    switch (in.step) {
      case Step::kState:
        r[k] = state[in.a][k];
        break;
      case Step::kAdd:
        r[k] = u[k] + w[k];
        break;
      case Step::kSub:
        r[k] = u[k] - w[k];
        break;
      case Step::kNeg:
        r[k] = -u[k];
        break;
      case Step::kScale:
        r[k] = u[k] * w[0];
        break;
      case Step::kMul:
        r[k] = Cauchy(0, k, u, w);
        break;
      case Step::kDivConst:
        r[k] = u[k] / w[0];
        break;
      case Step::kDiv:
        r[k] = (u[k] - Cauchy(1, k, w, r)) / w[0];
        break;
      case Step::kOther:
        Compute(in.node, k, state, nullptr, rows);
        break;
    }
  }
}

void Tape::Constants(const double* params, TaylorRow* rows) const {
  for (int i = 0; i < size(); ++i) {
    if (!constant_[i] || (!live_.empty() && !live_[i])) continue;
    std::fill(rows[i], rows[i] + kTaylorRowSize, 0.0);
    Compute(i, 0, nullptr, params, rows);
  }
}

void Tape::Compute(int i, int k, const TaylorRow* state, const double* params,
                   TaylorRow* rows) const {
  const Node& n = nodes_[i];
  double* r = rows[i];
  const bool input = n.op == Op::kState || n.op == Op::kParam || n.op == Op::kConst;
  const double* u = input ? r : rows[n.a];
  const double* w = input ? r : rows[n.b];
  switch (n.op) {
    case Op::kState:
      r[k] = state[n.a][k];
      break;
    case Op::kParam:
      r[k] = k == 0 ? params[n.a] : 0.0;
      break;
    case Op::kConst:
      r[k] = k == 0 ? n.c : 0.0;
      break;
    case Op::kAdd:
      r[k] = u[k] + w[k];
      break;
    case Op::kSub:
      r[k] = u[k] - w[k];
      break;
    case Op::kNeg:
      r[k] = -u[k];
      break;
    case Op::kMul:
      r[k] = constant_[n.a] ? u[0] * w[k] : constant_[n.b] ? u[k] * w[0] : Cauchy(0, k, u, w);
      break;
    case Op::kDiv:
      r[k] = constant_[n.b] ? u[k] / w[0] : (u[k] - Cauchy(1, k, w, r)) / w[0];
      break;
    case Op::kExp:
      r[k] = k == 0 ? std::exp(u[0]) : Weighted(k, u, r) / k;
      break;
    case Op::kLog:  // u l' = u': l_k = (u_k - (1/k) sum_{m=1..k-1} m l_m u_{k-m}) / u_0
      if (k == 0) {
        r[0] = std::log(u[0]);
      } else {
        double s = 0;
        for (int m = 1; m < k; ++m) s += m * r[m] * u[k - m];
        r[k] = (u[k] - s / k) / u[0];
      }
      break;
    case Op::kSin:
      r[k] = k == 0 ? std::sin(u[0]) : Weighted(k, u, w) / k;
      break;
    case Op::kCos:
      r[k] = k == 0 ? std::cos(u[0]) : -Weighted(k, u, w) / k;
      break;
    case Op::kSinh:
      r[k] = k == 0 ? std::sinh(u[0]) : Weighted(k, u, w) / k;
      break;
    case Op::kCosh:
      r[k] = k == 0 ? std::cosh(u[0]) : Weighted(k, u, w) / k;
      break;
    case Op::kPow:
      if (k == 0) {
        r[0] = std::pow(u[0], n.c);
      } else {  // u_0 k p_k = sum_{j=1..k} (c j - (k - j)) u_j p_{k-j}
        double s = 0;
        for (int j = 1; j <= k; ++j) s += (n.c * j - (k - j)) * u[j] * r[k - j];
        r[k] = s / (k * u[0]);
      }
      break;
  }
}

void Tape::Values(const double* z, const double* params, double* out) const {
  // The constants first: Fold's products are made after the nodes that use them.
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < size(); ++i)
      if (constant_[i] == (pass == 0) && (live_.empty() || live_[i])) Value(i, z, params, out);
}

void Tape::Value(int i, const double* z, const double* params, double* out) const {
  {
    const Node& n = nodes_[i];
    const bool input = n.op == Op::kState || n.op == Op::kParam || n.op == Op::kConst;
    const double u = input ? 0 : out[n.a], w = input ? 0 : out[n.b];
    switch (n.op) {
      case Op::kState:
        out[i] = z[n.a];
        break;
      case Op::kParam:
        out[i] = params[n.a];
        break;
      case Op::kConst:
        out[i] = n.c;
        break;
      case Op::kAdd:
        out[i] = u + w;
        break;
      case Op::kSub:
        out[i] = u - w;
        break;
      case Op::kNeg:
        out[i] = -u;
        break;
      case Op::kMul:
        out[i] = u * w;
        break;
      case Op::kDiv:
        out[i] = u / w;
        break;
      case Op::kExp:
        out[i] = std::exp(u);
        break;
      case Op::kLog:
        out[i] = std::log(u);
        break;
      case Op::kSin:
        out[i] = std::sin(u);
        break;
      case Op::kCos:
        out[i] = std::cos(u);
        break;
      case Op::kSinh:
        out[i] = std::sinh(u);
        break;
      case Op::kCosh:
        out[i] = std::cosh(u);
        break;
      case Op::kPow:
        out[i] = std::pow(u, n.c);
        break;
    }
  }
}

}  // namespace stickslip::model_file
