// Records GiNaC expressions onto a tape (tape.hpp): one node per distinct
// subexpression, the state's components and the parameters as inputs.
// Functions: exp, log, sin, cos, sinh, cosh, tanh and powers (sqrt is a
// power); anything else is refused by the checks before (symbolic.cpp).
//
// The same tape in every run. GiNaC orders a sum's terms by hashes seeded
// with type addresses, which vary from run to run, and with them how it
// spreads signs over a sum and its numeric factors: (B/p + 2) in one run is
// -(-B/p - 2) in the next. The recorder records magnitudes: each node carries
// a sign apart, a sum's terms are ordered by a key of their own structure
// (as text), and a sum whose first term is negative is recorded negated.
// Negation is exact, so every run computes the same bits.
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <vector>

#include "model_file/tape.hpp"

namespace stickslip::model_file {

class Recorder {
 public:
  /// The inputs: state symbols (kState i) and parameter symbols (kParam j).
  Recorder(Tape* tape, const std::vector<GiNaC::symbol>& state,
           const std::vector<GiNaC::symbol>& params);
  /// The node whose value is e (recorded on first sight).
  int Node(const GiNaC::ex& e);

 private:
  struct Signed {
    int node;
    int sign;  ///< e = sign * node
  };
  Signed Rec(const GiNaC::ex& e);
  Signed Record(const GiNaC::ex& e);
  Signed Sum(const GiNaC::ex& e);
  Signed Product(const GiNaC::ex& e);
  Signed Power(const GiNaC::ex& base, const GiNaC::ex& exponent);
  int Function(const std::string& f, const GiNaC::ex& arg);
  int Magnitude(const Signed& s);  // a node of the signed value itself
  // A node of this operation and key, made once per key.
  int Emit(const model_file::Node& n, const std::string& key);
  int Constant(double c);

  Tape* tape_;
  std::map<GiNaC::ex, Signed, GiNaC::ex_is_less> memo_;
  std::map<std::string, int> by_key_;
  std::vector<std::string> key_;  // per node
};

}  // namespace stickslip::model_file
