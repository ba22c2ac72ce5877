// Forward-mode differentiation on the tape (tape.hpp; Griewank & Walther
// 2008, ch. 3): each node's derivative in one input as new nodes, by the
// elementary rules, so that a parameter's column needs no symbolic algebra
// (GiNaC's diff of a stuck mode's large fields cost more than the modes).
#include <cmath>
#include <vector>

#include "model_file/tape.hpp"

namespace stickslip::model_file {

std::vector<int> Tape::Derivative(const std::vector<int>& outputs, Op input, int index) {
  const int n = size();
  const std::vector<bool> need = Reads(outputs);  // only the nodes an output reads
  std::vector<int> d(n, -1);                      // -1: the derivative is 0
  auto add = [&](int x, int y) { return x < 0 ? y : y < 0 ? x : Add({Op::kAdd, x, y, 0}); };
  auto mul = [&](int x, int y) { return x < 0 || y < 0 ? -1 : Add({Op::kMul, x, y, 0}); };
  auto neg = [&](int x) { return x < 0 ? -1 : Add({Op::kNeg, x, 0, 0}); };
  auto sub = [&](int x, int y) { return y < 0 ? x : x < 0 ? neg(y) : Add({Op::kSub, x, y, 0}); };
  auto div = [&](int x, int y) { return x < 0 ? -1 : Add({Op::kDiv, x, y, 0}); };
  auto constant = [&](double c) { return Add({Op::kConst, 0, 0, c}); };
  for (int i = 0; i < n; ++i) {
    if (!need[i]) continue;
    const Node nd = nodes_[i];
    const int da = nd.op == Op::kState || nd.op == Op::kParam || nd.op == Op::kConst ? -1 : d[nd.a];
    switch (nd.op) {
      case Op::kState:
      case Op::kParam:
        if (nd.op == input && nd.a == index) d[i] = constant(1);
        break;
      case Op::kConst:
        break;
      case Op::kAdd:
        d[i] = add(da, d[nd.b]);
        break;
      case Op::kSub:
        d[i] = sub(da, d[nd.b]);
        break;
      case Op::kMul:  // a' b + a b'
        d[i] = add(mul(da, nd.b), mul(nd.a, d[nd.b]));
        break;
      case Op::kDiv:  // (a' - (a / b) b') / b
        d[i] = div(sub(da, mul(i, d[nd.b])), nd.b);
        break;
      case Op::kNeg:
        d[i] = neg(da);
        break;
      case Op::kPow:  // c a^(c-1) a' (a_0 != 0, as for the node itself)
        if (da >= 0)
          d[i] = nd.c == 1 ? da : mul(mul(constant(nd.c), Add({Op::kPow, nd.a, 0, nd.c - 1})), da);
        break;
      case Op::kExp:  // exp(a) a'
        d[i] = mul(da, i);
        break;
      case Op::kLog:
        d[i] = div(da, nd.a);
        break;
      case Op::kSin:   // cos(a) a' (b: its cos)
      case Op::kSinh:  // cosh(a) a'
      case Op::kCosh:  // sinh(a) a'
        d[i] = mul(da, nd.b);
        break;
      case Op::kCos:  // -sin(a) a'
        d[i] = neg(mul(da, nd.b));
        break;
    }
  }
  int zero = -1;
  std::vector<int> out;
  for (int o : outputs) {
    if (d[o] < 0 && zero < 0) zero = constant(0);
    out.push_back(d[o] < 0 ? zero : d[o]);
  }
  return out;
}

}  // namespace stickslip::model_file
