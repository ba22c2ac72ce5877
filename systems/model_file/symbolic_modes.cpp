// A model file's modes, solved and recorded (compiler.hpp): in each, the
// slipping contacts' forces sigma N mu(s) with s = -sigma h (sigma = +1
// below the surface, -1 above), the sticking ones' from h' = 0
// (symbolic_solve.cpp).
#include <ginac/ginac.h>

#include <cmath>

#include "model_file/compiler.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/system/mode.hpp"

namespace stickslip::model_file {

using GiNaC::ex;

namespace {
constexpr std::size_t kMaxModelContacts = 4;  // 3^4 modes, each solved and recorded when read
}  // namespace

void Compiler::Symbols() {
  out_->source = spec_.source, out_->name = spec_.name;
  out_->k = static_cast<int>(spec_.contacts.size());
  for (std::size_t i = 0; i < spec_.coordinates.size(); ++i) {  // x, x' or w
    const std::string& x = spec_.coordinates[i];
    equation_of_.push_back(-1);  // x: its rate is the symbol x'
    state_.emplace_back(x);
    out_->state_names.push_back(x);
    if (spec_.orders[i] == 1) {
      equation_of_.back() = static_cast<int>(i);
      continue;
    }
    equation_of_.push_back(static_cast<int>(i));
    state_.emplace_back(MangleRates(x + "'"));
    out_->state_names.push_back(x + "'");
  }
  out_->n = static_cast<int>(state_.size());
  for (std::size_t t = 0; t < equation_of_.size(); ++t)
    out_->derivative_of.push_back(equation_of_[t] < 0 ? static_cast<int>(t) + 1 : -1);
  if (!spec_.clock.empty()) {
    state_.emplace_back(spec_.clock);
    out_->state_names.push_back(spec_.clock);
    out_->clocks = 1;
    ++out_->n;
    out_->derivative_of.push_back(-1);
  }
  for (const std::string& p : spec_.parameters) params_.emplace_back(p);
  for (const ContactSpec& c : spec_.contacts) forces_.emplace_back(c.name);
  out_->parameters = spec_.parameters;
  out_->defaults = spec_.defaults;
  out_->parameter_used.assign(params_.size(), false);
}

void Compiler::ParseContact(std::size_t c) {
  const ContactSpec& spec = spec_.contacts[c];
  velocity_.push_back(Parse(spec.velocity, true, false, false, "contact " + spec.name));
  out_->velocity.push_back(Linear(velocity_[c], spec.velocity, "contact " + spec.name));
  if (out_->clocks && out_->velocity.back().weight.back() >= 0)
    Fail(spec_.source, spec.velocity.line,
         "contact " + spec.name + " reads the clock " + spec_.clock + " (a phase, not a velocity)");
  bool moves = false;
  for (int w : out_->velocity.back().weight) moves = moves || w >= 0;
  if (!moves)
    Fail(spec_.source, spec.velocity.line,
         "contact " + spec.name + " = '" + spec.velocity.text +
             "' depends on no state component (a relative velocity such as x' - v)");
  std::vector<int> dh;  // d h_c / dp_j: the parameter column's crossing (ContactSensitivity)
  for (const GiNaC::symbol& q : params_) dh.push_back(contact_->Node(velocity_[c].diff(q)));
  out_->dvelocity.push_back(dh);
  law_.push_back(Parse(spec.law, false, false, true, "law " + spec.name));
  normal_.push_back(spec.normal.line ? Parse(spec.normal, true, false, false, "normal " + spec.name)
                                     : ex(1));
  out_->normal.push_back(Linear(normal_[c], spec.normal, "normal " + spec.name));
  bool varies = false;
  for (int w : out_->normal.back().weight) varies = varies || w >= 0;
  out_->normal_varies.push_back(varies);
  if (spec.static_limit.line) {
    static_.push_back(Parse(spec.static_limit, false, false, false, "static " + spec.name));
    out_->static_coefficient.push_back(contact_->Node(static_[c]));
  } else {
    try {  // the law at s = 0, where GiNaC may find log(0) or a pole
      static_.push_back(law_[c].subs(s_ == 0));
      out_->static_coefficient.push_back(contact_->Node(static_[c]));
    } catch (const std::exception&) {
      Fail(spec_.source, spec.law.line,
           "law " + spec.name + " = '" + spec.law.text +
               "' is not smooth at s = 0 (it has no value there), where every slip starts; a "
               "power of s needs a numeric whole exponent >= 0");
    }
  }
  out_->contact_names.push_back(spec.name);
  out_->static_lines.push_back(spec.static_limit.line ? spec.static_limit.line : spec.law.line);
}

void Compiler::ParseAll() {
  for (std::size_t i = 0; i < spec_.equations.size(); ++i)
    eq_.push_back(Parse(spec_.equations[i], true, true, false,
                        spec_.coordinates[i] + std::string(spec_.orders[i], '\'')));
  if (!spec_.clock.empty()) {
    clock_rate_ = Parse(spec_.clock_rate, false, false, false, "clock " + spec_.clock);
    out_->clock_rate = {contact_->Node(clock_rate_), spec_.clock_rate.line, spec_.clock_rate.text};
    for (const GiNaC::symbol& q : params_)
      out_->dclock_rate.push_back(contact_->Node(clock_rate_.diff(q)));
  }
  for (std::size_t c = 0; c < spec_.contacts.size(); ++c) ParseContact(c);
}

std::shared_ptr<const Compiled> Compiler::Run() {
  if (spec_.contacts.size() > kMaxModelContacts)
    Fail(spec_.source, spec_.contacts[kMaxModelContacts].velocity.line,
         "more than " + std::to_string(kMaxModelContacts) +
             " contacts: a model file's 3^k modes are solved when it is read (docs/limits.md)");
  Symbols();
  contact_ = std::make_unique<Recorder>(&out_->contact, state_, params_);
  try {
    ParseAll();
    std::vector<double> values(out_->contact.size()), z(state_.size(), 0.0);
    out_->contact.Values(z.data(), out_->defaults.data(), values.data());
    for (const Denominator& d : out_->denominators)
      if (!(values[d.node] != 0) || !std::isfinite(values[d.node]))
        Fail(spec_.source, d.line,
             "divides by " + d.text + " = " + Number(values[d.node]) +
                 " at the parameters' values given");
    for (std::size_t c = 0; c < spec_.contacts.size(); ++c) CheckLaw(c);
    CheckLinearInForces();
    int modes = 1;
    for (int c = 0; c < out_->k; ++c) modes *= 3;
    out_->modes.resize(modes);
    for (int m = 0; m < modes; ++m) Mode(m);
  } catch (const InvalidArgument&) {
    throw;
  } catch (const std::invalid_argument& e) {  // the recorder's refusal
    Fail(spec_.source, 0, std::string("cannot record ") + e.what());
  } catch (const std::exception& e) {  // GiNaC's or CLN's arithmetic
    Fail(spec_.source, 0, std::string("cannot evaluate the model: ") + e.what());
  }
  return out_;
}

void Compiler::Mode(int index) {
  ModeProgram& p = out_->modes[index];
  std::vector<stickslip::Mode> mode(out_->k);
  for (int c = 0, r = index; c < out_->k; ++c, r /= 3)
    mode[c] = static_cast<stickslip::Mode>(r % 3);
  GiNaC::exmap forces;
  std::vector<int> sticking;
  for (int c = 0; c < out_->k; ++c) {
    if (mode[c] == stickslip::Mode::kStick) {
      sticking.push_back(c);
      continue;
    }
    const int sigma = mode[c] == stickslip::Mode::kSlipBelow ? 1 : -1;
    forces[forces_[c]] = sigma * normal_[c] * law_[c].subs(s_ == -sigma * velocity_[c]);
  }
  std::vector<ex> rates;  // h_c' = sum_t dh_c/dz_t f_t, linear in the sticking forces
  for (int c : sticking) rates.push_back(VelocityRate(c, forces));
  std::vector<ex> lambdas;
  Solve(rates, sticking, &lambdas, &p.consistent);
  if (!p.consistent) return;  // singular: the stick forces are not determined
  for (std::size_t j = 0; j < sticking.size(); ++j) forces[forces_[sticking[j]]] = lambdas[j];
  std::vector<ex> field, aux;
  for (std::size_t t = 0; t < state_.size(); ++t)
    field.push_back(Rate(static_cast<int>(t), forces));
  for (int c = 0, q = 0; c < out_->k; ++c)
    if (mode[c] == stickslip::Mode::kStick)
      aux.insert(aux.end(), {lambdas[q++], static_[c] * normal_[c]});
  Record(p, field, aux, lambdas);
}

void Compiler::Record(ModeProgram& p, const std::vector<ex>& field, const std::vector<ex>& aux,
                      const std::vector<ex>& lambdas) {
  Recorder plain(&p.plain, state_, params_), full(&p.full, state_, params_);
  for (const ex& f : field) p.field.push_back(plain.Node(f)), p.full_field.push_back(full.Node(f));
  for (const ex& a : aux) p.aux.push_back(plain.Node(a)), p.full_aux.push_back(full.Node(a));
  const std::size_t tangent = state_.size() - out_->clocks;  // J leaves the clock out
  for (std::size_t r = 0; r < tangent; ++r)
    for (std::size_t u = 0; u < tangent; ++u)
      p.jacobian.push_back(full.Node(field[r].diff(state_[u])));
  for (const ex& l : lambdas) {
    std::vector<int> g;
    for (const GiNaC::symbol& z : state_) g.push_back(full.Node(l.diff(z)));
    p.lambda_gradient.push_back(g);
  }
  std::vector<int> plain_out = p.field, full_out = p.full_field;
  plain_out.insert(plain_out.end(), p.aux.begin(), p.aux.end());
  full_out.insert(full_out.end(), p.full_aux.begin(), p.full_aux.end());
  full_out.insert(full_out.end(), p.jacobian.begin(), p.jacobian.end());
  for (const std::vector<int>& g : p.lambda_gradient)
    full_out.insert(full_out.end(), g.begin(), g.end());
  RecordColumns(p, full_out);
  p.plain.Seal(plain_out);
  p.full.Seal(full_out);
}

// The parameter columns (compiled.hpp): per parameter j, a copy of the full
// tape's recording with d/dp_j (and df/dtheta) by forward-mode rules
// (Tape::Derivative), sealed on its outputs; before the full tape is sealed.
void Compiler::RecordColumns(ModeProgram& p, const std::vector<int>& full_out) {
  const std::vector<int> clock_rows(p.full_field.begin(), p.full_field.end() - out_->clocks);
  std::vector<int> rows = p.full_field;
  rows.insert(rows.end(), p.full_aux.begin(), p.full_aux.end());
  for (std::size_t j = 0; j < params_.size(); ++j) {
    Tape t = p.full;  // each copy carries its own parameter's nodes only
    // df/dtheta first: the same nodes in every copy.
    if (out_->clocks) p.dclock = t.Derivative(clock_rows, Op::kState, out_->n - 1);
    const std::vector<int> d = t.Derivative(rows, Op::kParam, static_cast<int>(j));
    p.dfield.emplace_back(d.begin(), d.begin() + out_->n);
    p.daux.emplace_back(d.begin() + out_->n, d.end());
    std::vector<int> outputs = full_out;
    for (const std::vector<int>* v : {&p.dclock, &p.dfield[j], &p.daux[j]})
      outputs.insert(outputs.end(), v->begin(), v->end());
    t.Seal(outputs);
    p.column.push_back(std::move(t));
  }
}

}  // namespace stickslip::model_file
