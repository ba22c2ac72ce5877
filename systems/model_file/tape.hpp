// A tape of elementary operations and their Taylor recurrences (Jorba & Zou
// 2005, section 3; Griewank & Walther, "Evaluating Derivatives", ch. 13;
// docs/model_files.md): a model file's fields, Jacobians and event rows,
// recorded once from their symbolic form (recorder.hpp) and run
// order by order. Inputs are the state's components and the parameters;
// outputs are nodes. Each operation's k-th coefficient costs O(k).
#pragma once

#include <vector>

#include "stickslip/system/taylor_field.hpp"

namespace stickslip::model_file {

enum class Op {
  kState,  ///< input: state component `a`
  kParam,  ///< input: parameter `a`
  kConst,  ///< the constant `c`
  kAdd,    ///< a + b
  kSub,    ///< a - b
  kMul,    ///< a b
  kDiv,    ///< a / b
  kNeg,    ///< -a
  kPow,    ///< a^c, c real (a_0 != 0)
  kExp,    ///< exp a
  kLog,    ///< log a
  kSin,    ///< sin a; b: its cos node
  kCos,    ///< cos a; b: its sin node
  kSinh,   ///< sinh a; b: its cosh node
  kCosh,   ///< cosh a; b: its sinh node
};

struct Node {
  Op op = Op::kConst;
  int a = 0, b = 0;
  double c = 0;
};

class Tape {
 public:
  /// Appends a node; returns its index. Arguments must be earlier nodes.
  int Add(const Node& n);
  /// The derivatives of `outputs` in one input (kState or kParam, its index),
  /// appended as nodes by forward-mode rules (tape_derivative.cpp); before
  /// Seal. A zero derivative is a constant node 0.
  std::vector<int> Derivative(const std::vector<int>& outputs, Op input, int index);
  /// Sets node i's second argument (a sin node's cos partner, made after it).
  void SetB(int i, int b) { nodes_[i].b = b; }
  /// Whether node i is constant in time (parameters and constants only): its
  /// coefficients past 0 vanish, and a product with it costs O(1) per order.
  bool constant(int i) const { return constant_[i]; }
  int size() const { return static_cast<int>(nodes_.size()); }
  const Node& node(int i) const { return nodes_[i]; }

  /// Prepares Order's program (after the last Add): a product of products or
  /// quotients by constants becomes one product by a constant node, and the
  /// nodes no output needs are left out.
  void Seal(const std::vector<int>& outputs);
  /// The constant nodes' rows (coefficient 0, zeros past it) at these
  /// parameters, those an output needs: once, before Order's calls on the
  /// same rows.
  void Constants(const double* params, TaylorRow* rows) const;
  /// Coefficient k of every node that varies, given coefficients 0..k of the
  /// state rows (state[i][j]); coefficients 0..k-1 of every node are in
  /// `rows` from the calls before (k = 0, 1, ... in turn), the constant
  /// nodes' from Constants.
  void Order(int k, const TaylorRow* state, TaylorRow* rows) const;
  /// The value at the point (coefficient 0 only) of every node an output
  /// needs (after Seal), else of every node.
  void Values(const double* z, const double* params, double* out) const;

 private:
  // Order visits the nodes that vary in time only, each as one of these (a
  // product or quotient with a constant is O(1) per order).
  enum class Step { kState, kAdd, kSub, kNeg, kScale, kMul, kDivConst, kDiv, kOther };
  struct Instr {
    Step step;
    int node, a, b;
  };
  void Compute(int i, int k, const TaylorRow* state, const double* params, TaylorRow* rows) const;
  void Value(int i, const double* z, const double* params, double* out) const;
  bool Scale(int i, int* base, int* factor);  // node i = base * factor, factor constant
  std::vector<bool> Reads(const std::vector<int>& outputs) const;  // the nodes they read
  void Fold();

  std::vector<Node> nodes_;
  std::vector<bool> constant_;
  std::vector<Instr> program_;
  std::vector<bool> live_;  // after Seal: the nodes an output needs (Values, Constants)
};

}  // namespace stickslip::model_file
