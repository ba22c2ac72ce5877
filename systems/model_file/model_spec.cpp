// A model file's lines (model_spec.hpp).
#include "model_file/model_spec.hpp"

#include <cctype>
#include <cmath>
#include <sstream>

#include "model_file/compiled.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::model_file {

namespace {

constexpr const char* kDot = "__dot";

std::string Trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

bool Identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return s.find(kDot) == std::string::npos;
}

// The words of "law F" / "parameter beta" before the '='.
std::vector<std::string> Words(const std::string& s) {
  std::istringstream is(s);
  std::vector<std::string> w;
  for (std::string x; is >> x;) w.push_back(x);
  return w;
}

class Reader {
 public:
  Reader(const std::string& source) { spec_.source = source; }
  ModelSpec Finish();
  void Line(const std::string& raw, int line);

 private:
  void Name(const std::string& name, int line) {
    if (!Identifier(name)) Fail(spec_.source, line, "'" + name + "' is not a name");
    static const char* reserved[] = {"s",    "t",    "I",      "Pi",     "Euler", "Catalan", "exp",
                                     "log",  "sin",  "cos",    "tan",    "sinh",  "cosh",    "tanh",
                                     "sqrt", "pow",  "abs",    "csgn",   "step",  "atan",    "asin",
                                     "acos", "zeta", "tgamma", "lgamma", "Order", "Li2"};
    for (const char* r : reserved)
      if (name == r)
        Fail(spec_.source, line,
             "'" + name +
                 "' is reserved (s: a law's slip speed; t: time; the others name GiNaC's "
                 "constants and functions)");
    for (const std::string& used : names_)
      if (used == name) Fail(spec_.source, line, "the name '" + name + "' is used twice");
    names_.push_back(name);
  }
  ContactSpec& ContactNamed(const std::string& name, int line, const std::string& key) {
    for (ContactSpec& c : spec_.contacts)
      if (c.name == name) return c;
    Fail(spec_.source, line,
         key + " " + name + ": no contact " + name + " (declare it: contact " + name + " = ...)");
  }
  void Coordinates(const std::string& value, int line, int order);
  void Parameter(const std::vector<std::string>& words, const std::string& value, int line);
  void Contact(const std::vector<std::string>& words, const std::string& value, int line);

  ModelSpec spec_;
  std::vector<std::string> names_;
  std::vector<std::pair<std::string, Located>> equations_;
  std::vector<int> equation_orders_;
};

// `coordinates = x, y` (order 2: x'' = ...) or `states = w` (order 1:
// w' = ...); the coordinates come first in the state.
void Reader::Coordinates(const std::string& value, int line, int order) {
  int& first = order == 2 ? spec_.coordinates_line : spec_.states_line;
  const char* key = order == 2 ? "coordinates" : "states";
  if (first)
    Fail(spec_.source, line,
         std::string("a second ") + key + " line (the first: line " + std::to_string(first) + ")");
  first = line;
  std::size_t at = 0;
  for (std::size_t i = 0; i < spec_.orders.size() && spec_.orders[i] == 2; ++i) at = i + 1;
  if (order == 1) at = spec_.orders.size();
  if (value.back() == ',') Name("", line);  // "x," names nothing after its comma
  std::string item;
  std::istringstream is(value);
  while (std::getline(is, item, ',')) {
    Name(Trim(item), line);
    spec_.coordinates.insert(spec_.coordinates.begin() + static_cast<long>(at), Trim(item));
    spec_.orders.insert(spec_.orders.begin() + static_cast<long>(at), order);
    ++at;
  }
}

void Reader::Parameter(const std::vector<std::string>& words, const std::string& value, int line) {
  if (words.size() != 2) Fail(spec_.source, line, "expected: parameter NAME = VALUE");
  Name(words[1], line);
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(x))
    Fail(spec_.source, line, "parameter " + words[1] + " = '" + value + "': not a finite number");
  spec_.parameters.push_back(words[1]);
  spec_.defaults.push_back(x);
  spec_.parameter_lines.push_back(line);
}

void Reader::Contact(const std::vector<std::string>& words, const std::string& value, int line) {
  if (words.size() != 2)
    Fail(spec_.source, line, "expected: " + words[0] + " NAME = EXPRESSION (NAME: the contact)");
  if (words[0] == "contact") {
    Name(words[1], line);
    ContactSpec c;
    c.name = words[1];
    c.velocity = {value, line};
    spec_.contacts.push_back(c);
    return;
  }
  ContactSpec& c = ContactNamed(words[1], line, words[0]);
  Located& slot = words[0] == "law" ? c.law : words[0] == "normal" ? c.normal : c.static_limit;
  if (slot.line)
    Fail(spec_.source, line,
         "a second " + words[0] + " for " + c.name + " (the first: line " +
             std::to_string(slot.line) + ")");
  slot = {value, line};
}

void Reader::Line(const std::string& raw, int line) {
  const std::string text = Trim(raw.substr(0, raw.find('#')));
  if (text.empty() || (text.front() == '[' && text.back() == ']')) return;
  const auto eq = text.find('=');
  if (eq == std::string::npos) Fail(spec_.source, line, "'" + text + "': expected KEY = VALUE");
  const std::string key = Trim(text.substr(0, eq)), value = Trim(text.substr(eq + 1));
  if (key.empty()) Fail(spec_.source, line, "no key before '='");
  if (value.empty()) Fail(spec_.source, line, key + ": no value after '='");
  const std::vector<std::string> words = Words(key);
  const int primes = key.size() > 2 && key.compare(key.size() - 2, 2, "''") == 0 ? 2
                     : key.size() > 1 && key.back() == '\''                      ? 1
                                                                                 : 0;
  if (primes) {
    equations_.push_back({Trim(key.substr(0, key.size() - primes)), {value, line}});
    equation_orders_.push_back(primes);
  } else if (key == "name") {
    spec_.name = value;
  } else if (key == "coordinates" || key == "states") {
    Coordinates(value, line, key == "coordinates" ? 2 : 1);
  } else if (words[0] == "clock") {
    if (words.size() != 2) Fail(spec_.source, line, "expected: clock NAME = RATE");
    if (!spec_.clock.empty()) Fail(spec_.source, line, "a second clock (one forcing phase only)");
    Name(words[1], line);
    spec_.clock = words[1];
    spec_.clock_rate = {value, line};
  } else if (words[0] == "parameter") {
    Parameter(words, value, line);
  } else if (words[0] == "contact" || words[0] == "law" || words[0] == "normal" ||
             words[0] == "static") {
    Contact(words, value, line);
  } else {
    Fail(spec_.source, line,
         "unknown key '" + key +
             "' (expected name, coordinates, states, parameter P, X'', W', contact F, law F, "
             "normal F, static F or clock T)");
  }
}

ModelSpec Reader::Finish() {
  if (spec_.coordinates.empty())
    Fail(spec_.source, 0, "no 'coordinates = x, ...' or 'states = w, ...' line");
  spec_.equations.assign(spec_.coordinates.size(), Located());
  auto lhs = [](const std::string& who, int order) { return who + std::string(order, '\''); };
  for (std::size_t q = 0; q < equations_.size(); ++q) {
    const auto& [who, e] = equations_[q];
    const int order = equation_orders_[q];
    std::size_t i = 0;
    while (i < spec_.coordinates.size() && spec_.coordinates[i] != who) ++i;
    if (i == spec_.coordinates.size())
      Fail(spec_.source, e.line,
           lhs(who, order) + " = ...: '" + who + "' is not a " +
               (order == 2 ? "coordinate" : "state (declare it: states = " + who + ")"));
    if (spec_.orders[i] != order)
      Fail(spec_.source, e.line,
           lhs(who, order) + " = ...: " + who + " is a " +
               (spec_.orders[i] == 2 ? "coordinate: write " : "first-order state: write ") +
               lhs(who, spec_.orders[i]) + " = ...");
    if (spec_.equations[i].line)
      Fail(spec_.source, e.line,
           "a second equation for " + lhs(who, order) + " (the first: line " +
               std::to_string(spec_.equations[i].line) + ")");
    spec_.equations[i] = e;
  }
  for (std::size_t i = 0; i < spec_.coordinates.size(); ++i)
    if (!spec_.equations[i].line)
      Fail(spec_.source, spec_.orders[i] == 2 ? spec_.coordinates_line : spec_.states_line,
           "no equation " + lhs(spec_.coordinates[i], spec_.orders[i]) + " = ... for " +
               (spec_.orders[i] == 2 ? "coordinate " : "state ") + spec_.coordinates[i] + " (" +
               std::to_string(spec_.coordinates.size()) +
               (spec_.states_line ? " coordinates and states, " : " coordinates, ") +
               std::to_string(equations_.size()) + " equations)");
  for (std::size_t i = 0; i < spec_.coordinates.size(); ++i)  // x's rate is the column xdot
    for (std::size_t j = 0; j < spec_.coordinates.size(); ++j)
      if (spec_.orders[i] == 2 && spec_.coordinates[j] == spec_.coordinates[i] + "dot")
        Fail(spec_.source, spec_.orders[j] == 2 ? spec_.coordinates_line : spec_.states_line,
             "the name '" + spec_.coordinates[j] + "' is the column of " + spec_.coordinates[i] +
                 "' in the tables: choose another");
  int components = 0;
  for (int order : spec_.orders) components += order;
  if (components < 2)
    Fail(spec_.source, spec_.states_line,
         "one state component: a model needs at least two (a coordinate x, or two states)");
  if (spec_.contacts.empty()) Fail(spec_.source, 0, "no 'contact F = ...' line");
  for (const ContactSpec& c : spec_.contacts)
    if (!c.law.line) Fail(spec_.source, c.velocity.line, "contact " + c.name + " has no law line");
  return spec_;
}

}  // namespace

void Fail(const std::string& source, int line, const std::string& problem) {
  std::string p = UnmangleRates(problem);  // one line: GiNaC's messages end in newlines
  for (char& c : p)
    if (c == '\n' || c == '\r') c = ' ';
  while (!p.empty() && p.back() == ' ') p.pop_back();
  throw InvalidArgument(source + (line ? ":" + std::to_string(line) : std::string()) + ": " + p);
}

std::string Number(double x) {
  std::ostringstream os;
  os.precision(12);
  os << x;
  return os.str();
}

ModelSpec ReadSpec(const std::string& text, const std::string& source) {
  Reader r(source);
  std::istringstream is(text);
  int line = 0;
  for (std::string raw; std::getline(is, raw);) r.Line(raw, ++line);
  ModelSpec spec = r.Finish();
  if (spec.name.empty()) {
    std::string stem = source.substr(source.find_last_of('/') + 1);
    spec.name = stem.substr(0, stem.find('.'));
  }
  return spec;
}

std::string ExactNumbers(const std::string& e, const std::string& source, int line) {
  std::string out;
  std::size_t i = 0;
  auto digit = [&](std::size_t k) {
    return k < e.size() && std::isdigit(static_cast<unsigned char>(e[k]));
  };
  while (i < e.size()) {
    const bool in_name =
        !out.empty() && (std::isalnum(static_cast<unsigned char>(out.back())) || out.back() == '_');
    if (in_name || !(digit(i) || (e[i] == '.' && digit(i + 1)))) {
      out += e[i++];
      continue;
    }
    const std::size_t start = i;
    std::string digits;
    int scale = 0;  // the value is digits x 10^scale
    for (; digit(i); ++i) digits += e[i];
    if (i < e.size() && e[i] == '.')
      for (++i; digit(i); ++i) digits += e[i], --scale;
    if (i < e.size() && (e[i] == 'e' || e[i] == 'E') &&
        (digit(i + 1) || ((e[i + 1] == '-' || e[i + 1] == '+') && digit(i + 2)))) {
      const std::size_t from = ++i;
      if (e[i] == '-' || e[i] == '+') ++i;
      while (digit(i)) ++i;
      const long x = std::strtol(e.substr(from, i - from).c_str(), nullptr, 10);
      if (std::labs(x) > 400 || i - from > 4)
        Fail(source, line, "the number '" + e.substr(start, i - start) + "' is beyond 1e+-400");
      scale += static_cast<int>(x);
    }
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
    if (scale >= 0) {
      out += "(" + digits + std::string(static_cast<std::size_t>(scale), '0') + ")";
    } else {
      out += "(" + digits + "/1" + std::string(static_cast<std::size_t>(-scale), '0') + ")";
    }
  }
  return out;
}

std::string MangleRates(const std::string& e) {
  std::string out;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const bool after_name =
        !out.empty() && (std::isalnum(static_cast<unsigned char>(out.back())) || out.back() == '_');
    if (e[i] == '\'' && after_name)
      out += kDot;
    else
      out += e[i];
  }
  return out;
}

std::string UnmangleRates(const std::string& text) {
  std::string out = text;
  for (std::size_t at; (at = out.find(kDot)) != std::string::npos;) out.replace(at, 5, "'");
  return out;
}

}  // namespace stickslip::model_file
