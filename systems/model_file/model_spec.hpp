// A model file's lines, read and sorted (model_file.hpp gives the grammar;
// docs/model_files.md): names, parameters with defaults, equations and
// contacts, each with the line it came from. Expressions are still text.
#pragma once

#include <string>
#include <vector>

namespace stickslip::model_file {

/// An expression's text and its line (0: not given).
struct Located {
  std::string text;
  int line = 0;
};

struct ContactSpec {
  std::string name;  ///< the force's symbol in the equations
  Located velocity, law, normal, static_limit;
};

struct ModelSpec {
  std::string source;  ///< the file, for messages
  std::string name;    ///< `name = ...`, else the file's stem
  /// The coordinates x (each gives the state x, x'), then the first-order
  /// states w (`states = w`: the state w alone), in declaration order.
  std::vector<std::string> coordinates;
  std::vector<int> orders;  ///< per name: 2 (x'' = ...) or 1 (w' = ...)
  int coordinates_line = 0, states_line = 0;
  std::vector<std::string> parameters;
  std::vector<double> defaults;
  std::vector<int> parameter_lines;
  std::vector<Located> equations;  ///< one per name of `coordinates`, in their order
  std::vector<ContactSpec> contacts;
  std::string clock;  ///< `clock theta = omega`: a phase state theta' = omega (empty: none)
  Located clock_rate;
};

/// Throws InvalidArgument "<source>:<line>: <problem>".
[[noreturn]] void Fail(const std::string& source, int line, const std::string& problem);
/// The lines of a model file, sorted and checked for form (names, numbers,
/// one equation per coordinate, a law per contact); the expressions are
/// checked by Compile (compiled.hpp, compiler.hpp).
ModelSpec ReadSpec(const std::string& text, const std::string& source);
/// Every decimal number of an expression as an exact fraction (0.25 ->
/// (25/100), 1e-3 -> (1/1000)): GiNaC then computes exactly, and the same in
/// every run (its floats made the stick forces' solution depend on term
/// order). Fails naming the line for an exponent beyond +-400.
std::string ExactNumbers(const std::string& expression, const std::string& source, int line);
/// x' -> x__dot (the symbols the parser reads), and back for messages.
std::string MangleRates(const std::string& expression);
std::string UnmangleRates(const std::string& text);

}  // namespace stickslip::model_file
