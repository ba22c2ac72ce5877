// The compiler of a model file (compiled.hpp): symbolic.cpp checks and
// parses its expressions, symbolic_modes.cpp builds and records each mode,
// symbolic_solve.cpp solves its sticking forces and checks the laws at s = 0.
#pragma once

#include <ginac/ginac.h>

#include <memory>
#include <string>
#include <vector>

#include "model_file/compiled.hpp"
#include "model_file/model_spec.hpp"
#include "model_file/recorder.hpp"

namespace stickslip::model_file {

class Compiler {
 public:
  explicit Compiler(const ModelSpec& spec) : spec_(spec) {}
  std::shared_ptr<const Compiled> Run();

 private:
  using ex = GiNaC::ex;
  void Symbols();
  void ParseAll();
  void ParseContact(std::size_t c);
  ex Parse(const Located& l, bool state, bool forces, bool slip, const std::string& what);
  void CheckPowers(const Located& l);
  void CheckSmooth(const ex& e, const Located& l);
  LinearForm Linear(const ex& e, const Located& l, const std::string& what);
  void Parameters(const ex& e, const Located& l);
  void CheckLinearInForces();
  void CheckLaw(std::size_t c);
  double At(const ex& e, const std::vector<double>& z) const;
  void Solve(const std::vector<ex>& rates, const std::vector<int>& sticking,
             std::vector<ex>* lambdas, bool* consistent) const;
  ex Rate(int t, const GiNaC::exmap& forces) const;  // f_t with the forces substituted
  ex VelocityRate(std::size_t c, const GiNaC::exmap& forces) const;  // h_c' = sum dh_c/dz_t f_t
  void Mode(int index);
  void Record(ModeProgram& p, const std::vector<ex>& field, const std::vector<ex>& aux,
              const std::vector<ex>& lambdas);
  void RecordColumns(ModeProgram& p, const std::vector<int>& full_out);

  const ModelSpec& spec_;
  std::vector<GiNaC::symbol> state_, params_, forces_;
  std::vector<int> equation_of_;  // per state component but the clock: its equation, -1: x -> x'
  GiNaC::symbol s_{"s"};
  std::vector<ex> eq_, velocity_, law_, normal_, static_;
  ex clock_rate_;  // the clock's frequency (parameters only)
  std::shared_ptr<Compiled> out_ = std::make_shared<Compiled>();
  std::unique_ptr<Recorder> contact_;
};

}  // namespace stickslip::model_file
