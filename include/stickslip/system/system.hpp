// The one system interface (docs/theory.md, "One core"; design after
// Filippov 1988 and Leine & Nijmeijer 2004): what the library needs of an
// autonomous friction system with state z in R^n and k contacts. The system
// describes its fields, contacts and parameters; the library owns stepping,
// events, switching, saltation, orbits and continuation. Implementable from
// the installed headers: see tests/system/seam_test.cpp.
//
// Conventions. Contact i has the relative velocity h_i(z) = w_i . z - s_i,
// linear in the state (ContactVelocity). In a mode (one Mode per contact,
// mode.hpp) the field is smooth; a sticking contact holds h_i = 0 by a
// constraint force lambda_i (StickForce), and sticks while |lambda_i| <=
// StaticLimit(i, z) (mu_s N_i). lambda_i > 0 means the contact, released,
// slips below (h_i < 0). The last clocks() components are phases theta with
// theta' = omega in every mode (a harmonic forcing, COCO's way of making a
// forced system autonomous): no field depends on them but through the
// forcing, and the variational equations leave them out (the tangent block
// is the first tangent_dimension() components).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>

#include "stickslip/system/mode.hpp"

namespace stickslip {

class TaylorField;  // taylor_field.hpp

/// h(z) = sum_t weight_t z_index_t - speed: a contact's relative velocity.
struct ContactVelocity {
  static constexpr int kMaxTerms = 4;
  struct Term {
    int index = 0;
    double weight = 1;
  };
  Term terms[kMaxTerms];
  int size = 0;  ///< terms used
  double speed = 0;
  double At(const double* z) const {
    double h = -speed;
    for (int t = 0; t < size; ++t) h += terms[t].weight * z[terms[t].index];
    return h;
  }
};

/// Empty if every contact's velocity has 1 to kMaxTerms terms, each of a
/// state component (clocks excluded) with a finite nonzero weight; else one
/// line naming the contact (the flow refuses such a system).
class System;
std::string ContactVelocityError(const System& s);

/// A contact's event functions differentiated in one parameter
/// (System::ContactParameterDerivative).
struct ContactSensitivity {
  double speed = 0, stick_force = 0, static_limit = 0;
};

/// What a Taylor field computes besides the state (taylor_field.hpp).
struct TaylorRequest {
  bool variational = false;      ///< Phi' = J Phi on the tangent block
  std::optional<int> parameter;  ///< the column dz/dp for this parameter index
};

using ConstState = Eigen::Ref<const Eigen::VectorXd>;
using StateOut = Eigen::Ref<Eigen::VectorXd>;
using MatrixOut = Eigen::Ref<Eigen::MatrixXd>;

class System {
 public:
  virtual ~System() = default;
  virtual std::unique_ptr<System> Clone() const = 0;
  /// Becomes a copy of s if s is of this type (no allocation); else false.
  virtual bool Assign(const System& s) = 0;
  /// Empty if the parameters are valid, else one line naming the offending value.
  virtual std::string ValidationError() const = 0;

  // --- Sizes and names ---
  virtual int dimension() const = 0;        ///< n
  virtual int contacts() const = 0;         ///< k >= 1
  virtual int clocks() const { return 0; }  ///< the last clocks() components are phases
  int tangent_dimension() const { return dimension() - clocks(); }
  /// "x", "x'", "theta": names for columns and messages.
  virtual std::string StateName(int i) const = 0;
  /// z_j = d z_i / dt in every mode (a second-order system), else -1: the
  /// flow then watches the extrema of z_i on the step polynomial of z_j.
  virtual int DerivativeOf(int /*i*/) const { return -1; }

  // --- Contacts ---
  virtual ContactVelocity Contact(int i) const = 0;
  /// lambda_i in mode m, where contact i sticks: the force that holds h_i = 0.
  virtual double StickForce(const ModeSet& m, int i, ConstState z) const = 0;
  /// d lambda_i / dz (n entries, clocks included).
  virtual void StickForceGradient(const ModeSet& m, int i, ConstState z, StateOut g) const = 0;
  /// mu_s,i N_i(z) > 0: contact i sticks while |lambda_i| <= this.
  virtual double StaticLimit(int i, ConstState z) const = 0;
  /// The normal force of contact i where it follows the state, as a linear
  /// functional N_i(z) = sum_t weight_t z_index_t - speed (ContactVelocity's
  /// form); empty (the default): a constant normal force, never open. The
  /// flow stops with FlowStatus::kContactOpen where N_i falls to 0: a run
  /// never continues as if an open contact were closed.
  virtual std::optional<ContactVelocity> NormalForce(int /*i*/) const { return std::nullopt; }
  /// d StaticLimit / dz (default: a constant limit, 0).
  virtual void StaticLimitGradient(int /*i*/, ConstState /*z*/, StateOut g) const { g.setZero(); }
  /// Moves z onto lambda_i(z) = bound exactly after a stick exit of contact
  /// i in mode m (m has i sticking). The default moves z along the gradient
  /// of lambda_i - StaticLimit_i in the components no sticking contact's
  /// velocity reads (one Newton step: exact where lambda is linear there).
  virtual void ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const;

  // --- Fields ---
  /// f(z) of mode m (n entries; a clock's entry is its frequency).
  virtual void Field(const ModeSet& m, ConstState z, StateOut f) const = 0;
  /// df/dz on the tangent block (tangent_dimension() square).
  virtual void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const = 0;
  /// The Taylor recurrences of the modes (taylor_field.hpp).
  virtual std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const = 0;
  /// Whether MakeTaylorField takes a column for parameter j. A system that
  /// says yes also gives the events' derivatives in j below (their defaults
  /// say the events do not depend on it).
  virtual bool SupportsParameterColumn(int /*j*/) const { return false; }
  /// d/dp_j of contact i's event functions at z (mode m has i sticking):
  /// speed = -dh/dp_j at z (the velocity's speed where only it depends on
  /// p_j; with weights that do, their dw/dp_j . z too), the stick force
  /// lambda_i and the static limit. The flow carries the column dz/dp across switches
  /// with them (the saltation of a parameter, docs/theory.md).
  virtual ContactSensitivity ContactParameterDerivative(const ModeSet& /*m*/, int /*i*/, int /*j*/,
                                                        ConstState /*z*/) const {
    return {};
  }
  /// d omega_c / dp_j of clock c's frequency (a clock's column is
  /// d theta / dp = (t - t0) d omega / dp).
  virtual double ClockRateDerivative(int /*c*/, int /*j*/) const { return 0; }
  /// An equilibrium of mode m's field, if it has one, and whether it is
  /// stable: near it the flow treats extrema as noise, and it ends a run
  /// that has settled on a stable one to within the integration noise.
  /// z holds a guess on entry (all 0: none) for a system that solves for
  /// it (a model file's Newton: the rest point nearest a branch's last).
  virtual bool Rest(const ModeSet& /*m*/, StateOut /*z*/, bool* /*stable*/) const { return false; }

  // --- Parameters (a lens is an index here) ---
  virtual int parameters() const = 0;
  virtual std::string ParameterName(int j) const = 0;
  /// Empty if the field depends on parameter j (0 <= j < parameters()), else
  /// one line naming it: a branch in it would not move (the belt's mu_m
  /// under the coulomb law). Every parameter applies unless overridden.
  virtual std::string ParameterError(int /*j*/) const { return ""; }
  virtual double ParameterValue(int j) const = 0;
  /// Sets parameter j (ValidationError() tells whether the result is valid).
  virtual void SetParameterValue(int j, double value) = 0;
  /// The index of a parameter by name; -1 if there is none.
  int ParameterIndex(const std::string& name) const;
};

}  // namespace stickslip
