// A model file compiled (symbolic.cpp): per mode, a tape whose outputs are
// the field, the sticking contacts' stick forces and static limits, and (in
// the full tape) the Jacobian and the stick forces' gradients; per contact,
// the linear forms of its velocity and normal force. Immutable once made,
// shared by every copy of the system.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model_file/tape.hpp"

namespace stickslip::model_file {

struct ModeProgram {
  bool consistent = true;       ///< false: the sticking set's stick forces are not determined
  Tape plain;                   ///< outputs: field, then aux (per sticking contact: lambda, limit)
  Tape full;                    ///< the same outputs, then J (row-major), then d lambda / dz
  std::vector<int> field, aux;  ///< node indexes in plain
  std::vector<int> full_field, full_aux;  ///< in full
  std::vector<int> jacobian;  ///< tangent x tangent (the clock left out), row-major, in full
  std::vector<std::vector<int>> lambda_gradient;  ///< per sticking contact, n, in full
  /// Per parameter j, the tape of a run with the column dz/dp_j: the full
  /// tape's outputs (the same node numbers: copies of its recording, each
  /// sealed on its own outputs) and df/dp_j (n), the aux rows' d/dp_j (as
  /// aux) and, with a clock, df/dtheta on the tangent block.
  std::vector<Tape> column;
  std::vector<std::vector<int>> dfield, daux;  ///< per parameter
  std::vector<int> dclock;                     ///< tangent entries
};

/// A linear form sum_t w_t z_t - speed, its w_t and speed as nodes of the
/// contact tape (functions of the parameters alone); -1: w_t is 0.
struct LinearForm {
  std::vector<int> weight;
  int speed = -1;
};

/// A parameter-only denominator: it may not be 0.
struct Denominator {
  int node = 0;  ///< in the contact tape
  int line = 0;
  std::string text;
};

struct Compiled {
  std::string source, name;
  int n = 0, k = 0, clocks = 0;  ///< the clock, if any, is the last state component
  std::vector<std::string> state_names, parameters;
  std::vector<int> derivative_of;  ///< per component: x -> the index of x', else -1
  std::vector<double> defaults;
  /// Per parameter: whether any expression of the file reads it (after
  /// GiNaC's own simplification); one that none reads is no axis to follow.
  std::vector<bool> parameter_used;
  std::vector<ModeProgram> modes;  ///< index sum_c mode_c 3^c (Mode's order)
  /// Parameter-only (and state-linear) quantities: per contact the velocity
  /// and normal forms, the static coefficient and the normal's constancy.
  Tape contact;
  std::vector<LinearForm> velocity, normal;
  std::vector<bool> normal_varies;
  std::vector<int> static_coefficient;  ///< nodes in contact
  std::vector<std::string> contact_names;
  std::vector<int> static_lines;  ///< the static line, else the law's
  std::vector<Denominator> denominators;
  /// The clock's rate (clocks: a node of the contact tape; it must be > 0).
  Denominator clock_rate{-1, 0, ""};
  /// d h_c / dp_j per contact and parameter (linear in the state) and the
  /// clock rate's d/dp_j, as nodes of the contact tape.
  std::vector<std::vector<int>> dvelocity;
  std::vector<int> dclock_rate;
};

/// A number for messages: %.12g.
std::string Number(double x);
/// Compiles a read spec; throws InvalidArgument "<file>:<line>: <problem>".
struct ModelSpec;
std::shared_ptr<const Compiled> Compile(const ModelSpec& spec);

}  // namespace stickslip::model_file
