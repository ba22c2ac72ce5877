// A model file's expressions, parsed and checked (compiler.hpp;
// docs/model_files.md): GiNaC parses and differentiates; every name must be
// known, every function smooth, every number's power bounded, each force
// linear in its equations and pushing its own contact's velocity up. The
// modes are solved in symbolic_modes.cpp and symbolic_solve.cpp.
#include <ginac/ginac.h>

#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "model_file/compiler.hpp"

namespace stickslip::model_file {

using GiNaC::ex;

ex Compiler::Parse(const Located& l, bool state, bool forces, bool slip, const std::string& what) {
  GiNaC::symtab table;
  if (state)
    for (const GiNaC::symbol& z : state_) table[z.get_name()] = z;
  if (forces)
    for (const GiNaC::symbol& f : forces_) table[f.get_name()] = f;
  for (const GiNaC::symbol& p : params_) table[p.get_name()] = p;
  if (slip) table["s"] = s_;
  GiNaC::parser reader(table, true);
  CheckPowers(l);
  const std::string exact = ExactNumbers(MangleRates(l.text), spec_.source, l.line);
  ex e;
  try {
    e = reader(exact);
  } catch (const std::exception& x) {
    std::string m = x.what();  // "GiNaC: parse error at line 0, column 0: ..."
    const auto at = m.find(": ", m.find("column"));
    if (m.rfind("GiNaC: parse error", 0) == 0 && at != std::string::npos)
      m = "parse error: " + m.substr(at + 2);
    const auto q = m.find("symbol \"");
    if (q != std::string::npos && m.find("not found") != std::string::npos)
      m = "unknown name " + m.substr(q + 7, m.find('"', q + 8) - q - 6) +
          " (not a coordinate, a rate x', a state, a parameter" +
          (forces ? ", a contact force" : "") + (slip ? " or the slip speed s" : "") + ")";
    Fail(spec_.source, l.line, what + " = '" + l.text + "': " + m);
  }
  CheckSmooth(e, l);
  Parameters(e, l);
  for (std::size_t j = 0; j < params_.size(); ++j)
    if (e.has(params_[j])) out_->parameter_used[j] = true;
  return e;
}

// GiNaC evaluates a number's power exactly when it parses it: 9^(9^9) would
// take hours. Exponents are a number up to kMaxExponent, or an expression
// without a power of its own.
void Compiler::CheckPowers(const Located& l) {
  constexpr double kMaxExponent = 1000;
  constexpr int kMaxDepth = 64;  // GiNaC's parser recurses per parenthesis
  const std::string& t = l.text;
  int depth = 0;
  for (char c : t)
    if ((depth += c == '(' ? 1 : c == ')' ? -1 : 0) > kMaxDepth)
      Fail(spec_.source, l.line, "parentheses nested deeper than 64");
  for (std::size_t at = t.find('^'); at != std::string::npos; at = t.find('^', at + 1)) {
    std::size_t i = t.find_first_not_of(" +-", at + 1);  // a sign first: 9^-(...) too
    if (i == std::string::npos) break;
    if (t[i] == '(') {
      int depth = 0;
      std::size_t j = i;
      for (; j < t.size(); ++j) {
        depth += t[j] == '(' ? 1 : t[j] == ')' ? -1 : 0;
        if (depth == 0) break;
      }
      const std::string inner = t.substr(i + 1, j > i ? j - i - 1 : 0);
      if (inner.find('^') != std::string::npos)
        Fail(spec_.source, l.line, "'" + t + "': a power in an exponent is refused");
      // Without a name it is a number GiNaC evaluates exactly: one number, up to 1000.
      bool named = false;
      for (char c : inner) named = named || std::isalpha(static_cast<unsigned char>(c)) || c == '_';
      char* end = nullptr;
      const double x = std::strtod(inner.c_str(), &end);
      const bool one_number =
          end != inner.c_str() &&
          inner.find_first_not_of(" ", end - inner.c_str()) == std::string::npos;
      if (!named && !(one_number && std::abs(x) <= kMaxExponent))
        Fail(spec_.source, l.line,
             "'" + t + "': the exponent (" + inner +
                 ") must be one number up to 1000, or an expression of the parameters or state");
      continue;
    }
    char* end = nullptr;
    const double x = std::strtod(t.c_str() + i, &end);
    if (end != t.c_str() + i && !(std::abs(x) <= kMaxExponent))
      Fail(spec_.source, l.line,
           "'" + t + "': the exponent " +
               t.substr(i, static_cast<std::size_t>(end - t.c_str()) - i) + " is above 1000");
  }
}

void Compiler::CheckSmooth(const ex& e, const Located& l) {
  static const std::set<std::string> smooth = {"exp", "log", "sin", "cos", "sinh", "cosh", "tanh"};
  static const std::set<std::string> kinks = {"abs", "csgn", "step", "Heaviside", "sign"};
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::numeric>(*it) && !GiNaC::ex_to<GiNaC::numeric>(*it).is_real())
      Fail(spec_.source, l.line, "'" + l.text + "' has a complex number");
    if (!GiNaC::is_a<GiNaC::function>(*it)) continue;
    const std::string f = GiNaC::ex_to<GiNaC::function>(*it).get_name();
    if (kinks.count(f))
      Fail(spec_.source, l.line,
           f + " is not smooth: write each mode's smooth expression (a law for s >= 0; "
               "the sign of the slip is the mode's)");
    if (!smooth.count(f))
      Fail(spec_.source, l.line,
           "the function " + f +
               " is not supported (exp, log, sin, cos, sinh, cosh, tanh, sqrt "
               "and powers are)");
  }
}

// Every parameter-only denominator is recorded: it may not be 0.
void Compiler::Parameters(const ex& e, const Located& l) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::power>(*it)) continue;
    const ex base = it->op(0), expo = it->op(1);
    bool state = false;
    for (const GiNaC::symbol& z : state_) state = state || base.has(z);
    for (const GiNaC::symbol& f : forces_) state = state || base.has(f);
    state = state || base.has(s_);
    if (state || GiNaC::is_a<GiNaC::numeric>(base) || !GiNaC::is_a<GiNaC::numeric>(expo) ||
        !GiNaC::ex_to<GiNaC::numeric>(expo).is_negative())
      continue;
    std::ostringstream text;
    text << base;
    out_->denominators.push_back({contact_->Node(base), l.line, text.str()});
  }
}

LinearForm Compiler::Linear(const ex& e, const Located& l, const std::string& what) {
  LinearForm form;
  int terms = 0;
  GiNaC::exmap zero;
  for (const GiNaC::symbol& z : state_) zero[z] = 0;
  for (const GiNaC::symbol& z : state_) {
    const ex d = e.diff(z);
    for (const GiNaC::symbol& u : state_)
      if (d.has(u))
        Fail(spec_.source, l.line,
             what + " '" + l.text + "' is not linear in the state (its derivative in " +
                 z.get_name() + " depends on " + u.get_name() + ")");
    form.weight.push_back(d.is_zero() ? -1 : contact_->Node(d));
    terms += !d.is_zero();
  }
  if (terms > 4)
    Fail(spec_.source, l.line, what + " '" + l.text + "' reads more than 4 state components");
  form.speed = contact_->Node(-e.subs(zero));
  return form;
}

// The value of a parameter-and-state expression at the parameters' defaults
// and the state z (NaN if it is not a finite real number there).
double Compiler::At(const ex& e, const std::vector<double>& z) const {
  GiNaC::exmap at;
  for (std::size_t t = 0; t < state_.size(); ++t) at[state_[t]] = z[t];
  for (std::size_t j = 0; j < params_.size(); ++j) at[params_[j]] = spec_.defaults[j];
  try {
    const ex v = GiNaC::evalf(e.subs(at));
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return NAN;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  } catch (const std::exception&) {
    return NAN;
  }
}

// Each force enters linearly (its derivative free of every force: no F^2,
// 1/F or F G), somewhere, and pushes its own contact's velocity up: the
// coefficient of F in h'' is > 0 at the defaults and the state 0 (as the
// belt's x'' = ... + F, so that lambda > 0 means it would slip below).
void Compiler::CheckLinearInForces() {
  const std::vector<double> zero(state_.size(), 0.0);
  for (std::size_t c = 0; c < forces_.size(); ++c) {
    bool used = false;
    const std::string& name = spec_.contacts[c].name;
    for (std::size_t i = 0; i < eq_.size(); ++i) {
      const ex d = eq_[i].diff(forces_[c]);
      for (const GiNaC::symbol& f : forces_)
        if (d.has(f))
          Fail(spec_.source, spec_.equations[i].line,
               "the force " + name + " enters " + spec_.coordinates[i] +
                   std::string(spec_.orders[i], '\'') +
                   " = ... nonlinearly (it must be a sum of terms coefficient * " + name +
                   ", the coefficient free of every force)");
      used = used || !d.is_zero();
    }
    if (!used)
      Fail(spec_.source, spec_.contacts[c].velocity.line,
           "the force " + name + " appears in no equation");
    const double own = At(VelocityRate(c, GiNaC::exmap()).diff(forces_[c]), zero);
    if (!(own > 0))
      Fail(spec_.source, spec_.contacts[c].velocity.line,
           "the force " + name +
               (own < 0 ? " pulls its own velocity '" : " does not act on its own velocity '") +
               spec_.contacts[c].velocity.text +
               (own < 0 ? "' down (its coefficient in the equations must be > 0: write the law's "
                          "sign into the equation as + " +
                              name + ")"
                        : "' (it cannot hold it at 0 in stick)"));
  }
}

ex Compiler::VelocityRate(std::size_t c, const GiNaC::exmap& forces) const {
  ex rate = 0;
  for (std::size_t t = 0; t < state_.size(); ++t)
    rate += velocity_[c].diff(state_[t]) * Rate(static_cast<int>(t), forces);
  return rate;
}

ex Compiler::Rate(int t, const GiNaC::exmap& forces) const {
  if (t >= static_cast<int>(equation_of_.size())) return clock_rate_;  // theta' = omega
  const int e = equation_of_[static_cast<std::size_t>(t)];
  return e < 0 ? ex(state_[t + 1]) : eq_[static_cast<std::size_t>(e)].subs(forces);
}

}  // namespace stickslip::model_file
