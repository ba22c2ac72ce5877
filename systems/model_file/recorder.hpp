// Records GiNaC expressions onto a tape (tape.hpp): one node per distinct
// subexpression, the state's components and the parameters as inputs.
// Functions: exp, log, sin, cos, sinh, cosh, tanh and powers (sqrt is a
// power); anything else is refused by the checks before (symbolic.cpp).
// GiNaC orders a sum's terms and a product's factors by hashes seeded with
// type addresses, which vary from run to run; the recorder orders them by a
// key of its own (their structure as text), so that a model's tape, and its
// rounding, is the same in every run.
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
  /// The node of e (recorded on first sight).
  int Node(const GiNaC::ex& e);

 private:
  int Record(const GiNaC::ex& e);
  int Power(const GiNaC::ex& base, const GiNaC::ex& exponent);
  int Product(const GiNaC::ex& e);
  int Pair(Op first, Op second, const GiNaC::ex& arg, bool want_second);
  int Constant(double c);
  const std::string& Key(const GiNaC::ex& e);
  std::vector<GiNaC::ex> Sorted(const GiNaC::ex& e);

  Tape* tape_;
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> memo_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> keys_;
};

}  // namespace stickslip::model_file
