// GiNaC expressions onto a tape, the same in every run (recorder.hpp).
#include "model_file/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace stickslip::model_file {

using GiNaC::ex;

Recorder::Recorder(Tape* tape, const std::vector<GiNaC::symbol>& state,
                   const std::vector<GiNaC::symbol>& params)
    : tape_(tape) {
  for (std::size_t i = 0; i < state.size(); ++i)
    memo_[state[i]] = {Emit({Op::kState, static_cast<int>(i), 0, 0}, "z" + std::to_string(i)), 1};
  for (std::size_t j = 0; j < params.size(); ++j)
    memo_[params[j]] = {Emit({Op::kParam, static_cast<int>(j), 0, 0}, "p" + std::to_string(j)), 1};
}

int Recorder::Emit(const model_file::Node& n, const std::string& key) {
  const auto it = by_key_.find(key);
  if (it != by_key_.end()) return it->second;
  const int i = tape_->Add(n);
  key_.resize(i + 1);
  key_[i] = key;
  by_key_[key] = i;
  return i;
}

int Recorder::Constant(double c) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "c%.17g", c);
  return Emit({Op::kConst, 0, 0, c}, buf);
}

int Recorder::Magnitude(const Signed& s) {
  return s.sign > 0 ? s.node : Emit({Op::kNeg, s.node, 0, 0}, "-(" + key_[s.node] + ")");
}

int Recorder::Node(const ex& e) { return Magnitude(Rec(e)); }

Recorder::Signed Recorder::Rec(const ex& e) {
  const auto it = memo_.find(e);
  if (it != memo_.end()) return it->second;
  const Signed s = Record(e);
  memo_[e] = s;
  return s;
}

// The terms by their keys; the first positive (else the sum is negated).
Recorder::Signed Recorder::Sum(const ex& e) {
  std::vector<Signed> terms;
  for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(Rec(e.op(i)));
  std::sort(terms.begin(), terms.end(),
            [this](const Signed& a, const Signed& b) { return key_[a.node] < key_[b.node]; });
  const int flip = terms[0].sign;
  int acc = terms[0].node;
  std::string key = "+(" + key_[acc];
  for (std::size_t i = 1; i < terms.size(); ++i) {
    const bool plus = terms[i].sign * flip > 0;
    key += std::string(plus ? ",+" : ",-") + key_[terms[i].node];
    acc = Emit({plus ? Op::kAdd : Op::kSub, acc, terms[i].node, 0}, key + ")");
  }
  return {acc, flip};
}

// The factors by their keys, those with negative numeric exponents dividing.
Recorder::Signed Recorder::Product(const ex& e) {
  std::vector<int> num, den;
  int sign = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    const ex f = e.op(i);
    const bool divides = GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
                         GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative();
    const Signed s = Rec(divides ? GiNaC::pow(f.op(0), -f.op(1)) : f);
    sign *= s.sign;
    if (tape_->node(s.node).op == Op::kConst && tape_->node(s.node).c == 1) continue;
    (divides ? den : num).push_back(s.node);
  }
  auto fold = [this](std::vector<int>& v) {
    std::sort(v.begin(), v.end(), [this](int a, int b) { return key_[a] < key_[b]; });
    if (v.empty()) return Constant(1);
    int acc = v[0];
    std::string key = "*(" + key_[acc];
    for (std::size_t i = 1; i < v.size(); ++i) {
      key += "," + key_[v[i]];
      acc = Emit({Op::kMul, acc, v[i], 0}, key + ")");
    }
    return acc;
  };
  const int n = fold(num);
  if (den.empty()) return {n, sign};
  const int d = fold(den);
  return {Emit({Op::kDiv, n, d, 0}, "/(" + key_[n] + "," + key_[d] + ")"), sign};
}

Recorder::Signed Recorder::Power(const ex& base, const ex& exponent) {
  if (!GiNaC::is_a<GiNaC::numeric>(exponent))  // b^e = exp(e log b)
    return Rec(GiNaC::exp(exponent * GiNaC::log(base)));
  const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(exponent);
  const Signed b = Rec(base);
  if (q.is_integer() && GiNaC::abs(q) <= GiNaC::numeric(1000)) {  // the parser's bound
    const int k = std::abs(q.to_int());
    if (k == 0) return {Constant(1), 1};
    int result = -1, square = b.node;  // by squaring
    for (int r = k; r; r >>= 1) {
      if (r & 1)
        result = result < 0 ? square
                            : Emit({Op::kMul, result, square, 0},
                                   "*(" + key_[result] + "," + key_[square] + ")");
      if (r > 1) square = Emit({Op::kMul, square, square, 0}, "*(" + key_[square] + ",2)");
    }
    const int sign = k % 2 ? b.sign : 1;
    if (q.is_positive()) return {result, sign};
    return {Emit({Op::kDiv, Constant(1), result, 0}, "/(1," + key_[result] + ")"), sign};
  }
  const int arg = Magnitude(b);
  char buf[40];
  std::snprintf(buf, sizeof buf, ",%.17g)", q.to_double());
  return {Emit({Op::kPow, arg, 0, q.to_double()}, "^(" + key_[arg] + buf), 1};
}

// sin and cos (sinh and cosh) of one argument are a pair of nodes, each the
// other's partner in the recurrences.
int Recorder::Function(const std::string& f, const ex& a) {
  const int arg = Magnitude(Rec(a));
  const std::string k = "(" + key_[arg] + ")";
  if (f == "exp") return Emit({Op::kExp, arg, 0, 0}, "exp" + k);
  if (f == "log") return Emit({Op::kLog, arg, 0, 0}, "log" + k);
  const bool trig = f == "sin" || f == "cos", hyper = f == "sinh" || f == "cosh" || f == "tanh";
  if (!trig && !hyper) throw std::invalid_argument("the function " + f);
  const std::string s = trig ? "sin" : "sinh", c = trig ? "cos" : "cosh";
  int first = by_key_.count(s + k) ? by_key_[s + k] : -1;
  if (first < 0) {
    first = Emit({trig ? Op::kSin : Op::kSinh, arg, 0, 0}, s + k);
    tape_->SetB(first, Emit({trig ? Op::kCos : Op::kCosh, arg, first, 0}, c + k));
  }
  const int second = by_key_[c + k];
  if (f == "tanh")
    return Emit({Op::kDiv, first, second, 0}, "/(" + key_[first] + "," + key_[second] + ")");
  return f == s ? first : second;
}

Recorder::Signed Recorder::Record(const ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!q.is_real()) throw std::invalid_argument("a complex number");
    const double c = q.to_double();
    return {Constant(std::abs(c)), c < 0 ? -1 : 1};
  }
  if (GiNaC::is_a<GiNaC::add>(e)) return Sum(e);
  if (GiNaC::is_a<GiNaC::mul>(e)) return Product(e);
  if (GiNaC::is_a<GiNaC::power>(e)) return Power(e.op(0), e.op(1));
  if (GiNaC::is_a<GiNaC::function>(e))
    return {Function(GiNaC::ex_to<GiNaC::function>(e).get_name(), e.op(0)), 1};
  throw std::invalid_argument("an expression of this kind");
}

}  // namespace stickslip::model_file
