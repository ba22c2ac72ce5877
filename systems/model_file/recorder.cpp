// GiNaC expressions onto a tape (recorder.hpp).
#include "model_file/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace stickslip::model_file {

using GiNaC::ex;

Recorder::Recorder(Tape* tape, const std::vector<GiNaC::symbol>& state,
                   const std::vector<GiNaC::symbol>& params)
    : tape_(tape) {
  for (std::size_t i = 0; i < state.size(); ++i)
    memo_[state[i]] = tape_->Add({Op::kState, static_cast<int>(i), 0, 0});
  for (std::size_t j = 0; j < params.size(); ++j)
    memo_[params[j]] = tape_->Add({Op::kParam, static_cast<int>(j), 0, 0});
}

int Recorder::Node(const ex& e) {
  const auto it = memo_.find(e);
  if (it != memo_.end()) return it->second;
  const int n = Record(e);
  memo_[e] = n;
  return n;
}

int Recorder::Constant(double c) { return Node(GiNaC::numeric(c)); }

const std::string& Recorder::Key(const ex& e) {
  const auto it = keys_.find(e);
  if (it != keys_.end()) return it->second;
  std::string key;
  if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e)) {
    std::ostringstream os;
    os << e;
    key = os.str();
  } else {
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < e.nops(); ++i) parts.push_back(Key(e.op(i)));
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e))
      std::sort(parts.begin(), parts.end());
    key = GiNaC::is_a<GiNaC::add>(e)        ? "+"
          : GiNaC::is_a<GiNaC::mul>(e)      ? "*"
          : GiNaC::is_a<GiNaC::power>(e)    ? "^"
          : GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name()
                                            : "?";
    key += "(";
    for (const std::string& p : parts) key += p + ",";
    key += ")";
  }
  return keys_[e] = key;
}

// A sum's terms or a product's factors in the order of their keys.
std::vector<ex> Recorder::Sorted(const ex& e) {
  std::vector<ex> ops;
  for (std::size_t i = 0; i < e.nops(); ++i) ops.push_back(e.op(i));
  std::sort(ops.begin(), ops.end(), [this](const ex& a, const ex& b) { return Key(a) < Key(b); });
  return ops;
}

// sin and cos (sinh and cosh) of one argument are one pair of nodes, each
// the other's partner in the recurrences.
int Recorder::Pair(Op first, Op second, const ex& arg, bool want_second) {
  const int a = Node(arg);
  const int f = tape_->Add({first, a, 0, 0});
  const int s = tape_->Add({second, a, f, 0});
  tape_->SetB(f, s);
  const bool trig = first == Op::kSin;
  memo_[trig ? GiNaC::sin(arg) : GiNaC::sinh(arg)] = f;
  memo_[trig ? GiNaC::cos(arg) : GiNaC::cosh(arg)] = s;
  return want_second ? s : f;
}

int Recorder::Power(const ex& base, const ex& exponent) {
  if (!GiNaC::is_a<GiNaC::numeric>(exponent))  // b^e = exp(e log b)
    return Node(GiNaC::exp(exponent * GiNaC::log(base)));
  const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(exponent);
  if (q.is_integer() && std::abs(q.to_int()) <= 64) {
    int k = q.to_int();
    if (k == 0) return Constant(1);
    const bool inverse = k < 0;
    k = std::abs(k);
    int result = -1, square = Node(base);  // by squaring
    for (; k; k >>= 1) {
      if (k & 1) result = result < 0 ? square : tape_->Add({Op::kMul, result, square, 0});
      if (k > 1) square = tape_->Add({Op::kMul, square, square, 0});
    }
    return inverse ? tape_->Add({Op::kDiv, Constant(1), result, 0}) : result;
  }
  return tape_->Add({Op::kPow, Node(base), 0, q.to_double()});
}

// A product: the factors with negative numeric exponents divide.
int Recorder::Product(const ex& e) {
  int num = -1, den = -1;
  auto times = [&](int acc, int f) { return acc < 0 ? f : tape_->Add({Op::kMul, acc, f, 0}); };
  for (const ex& f : Sorted(e)) {
    if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative())
      den = times(den, Node(GiNaC::pow(f.op(0), -f.op(1))));
    else
      num = times(num, Node(f));
  }
  if (num < 0) num = Constant(1);
  return den < 0 ? num : tape_->Add({Op::kDiv, num, den, 0});
}

int Recorder::Record(const ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!q.is_real()) throw std::invalid_argument("a complex number");
    return tape_->Add({Op::kConst, 0, 0, q.to_double()});
  }
  if (GiNaC::is_a<GiNaC::add>(e)) {
    const std::vector<ex> terms = Sorted(e);
    int acc = Node(terms[0]);
    for (std::size_t i = 1; i < terms.size(); ++i) {
      const ex& t = terms[i];
      // a + (-1) b: a subtraction
      if (GiNaC::is_a<GiNaC::mul>(t) && t.op(t.nops() - 1).is_equal(-1))
        acc = tape_->Add({Op::kSub, acc, Node(-t), 0});
      else
        acc = tape_->Add({Op::kAdd, acc, Node(t), 0});
    }
    return acc;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    if (e.op(e.nops() - 1).is_equal(-1)) return tape_->Add({Op::kNeg, Node(-e), 0, 0});
    return Product(e);
  }
  if (GiNaC::is_a<GiNaC::power>(e)) return Power(e.op(0), e.op(1));
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string f = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const ex a = e.op(0);
    if (f == "exp") return tape_->Add({Op::kExp, Node(a), 0, 0});
    if (f == "log") return tape_->Add({Op::kLog, Node(a), 0, 0});
    if (f == "sin" || f == "cos") return Pair(Op::kSin, Op::kCos, a, f == "cos");
    if (f == "sinh" || f == "cosh") return Pair(Op::kSinh, Op::kCosh, a, f == "cosh");
    if (f == "tanh") return tape_->Add({Op::kDiv, Node(GiNaC::sinh(a)), Node(GiNaC::cosh(a)), 0});
    throw std::invalid_argument("the function " + f);
  }
  throw std::invalid_argument("an expression of this kind");
}

}  // namespace stickslip::model_file
