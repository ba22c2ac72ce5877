// A chain of N blocks on a belt (docs/theory.md, "A chain of blocks"),
// written from the installed headers only (system.hpp, taylor_field.hpp,
// friction.hpp):
//   m_i x_i'' + c_i x_i' + k_i x_i + kc sum_j (x_i - x_j) = F_i(x_i' - v),
// j the neighbours of i (open ends), F_i the slip force of block i's own
// friction law (seed eq. 3.5). Block i sticks, x_i' = v, while
// |c_i v + k_i x_i + kc sum_j (x_i - x_j)| <= mu_s,i (Popp & Stelter 1990;
// Galvanetto, JSV 248, 2001). State z = (x_1, x_1', ..., x_N, x_N').
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "stickslip/system/system.hpp"
#include "stickslip/systems/belt/friction.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip::chain {

/// One block: mass, damping, spring to the ground, and its contact's law
/// (law, mu_s and the law's own parameters; its beta and v are not read).
struct Block {
  double m = 1, c = 0.1, k = 1;
  Params law;
};

struct ChainParams {
  double v = 0.25;  ///< belt speed (> 0)
  double kc = 0;    ///< the spring between neighbours (>= 0)
  std::vector<Block> blocks;
};

/// n identical blocks with the dimensionless defaults m = 1, c = 2 beta,
/// k = 1 and p's law; belt speed p.v.
ChainParams Uniform(int n, const Params& p, double kc);

class Chain final : public System {
 public:
  /// Throws InvalidArgument naming the offending value.
  explicit Chain(const ChainParams& p);
  const ChainParams& params() const { return p_; }
  int blocks() const { return static_cast<int>(p_.blocks.size()); }
  const Friction& friction(int i) const { return friction_[i]; }
  /// k_i + kc (number of neighbours): the diagonal of the stiffness.
  double Stiffness(int i) const { return p_.blocks[i].k + p_.kc * Neighbours(i); }
  int Neighbours(int i) const { return (i > 0) + (i + 1 < blocks()); }
  /// k_i x_i + kc sum_j (x_i - x_j): the springs' force on block i.
  double Spring(int i, const double* z) const;
  /// c_i v + Spring: the force that holds block i on the belt.
  double HoldingForce(int i, const double* z) const { return p_.blocks[i].c * p_.v + Spring(i, z); }

  std::unique_ptr<System> Clone() const override { return std::make_unique<Chain>(*this); }
  bool Assign(const System& s) override;
  std::string ValidationError() const override;

  int dimension() const override { return 2 * blocks(); }
  int contacts() const override { return blocks(); }
  std::string StateName(int i) const override;
  int DerivativeOf(int i) const override { return i % 2 == 0 ? i + 1 : -1; }

  ContactVelocity Contact(int i) const override;
  double StickForce(const ModeSet&, int i, ConstState z) const override {
    return HoldingForce(i, z.data());
  }
  void StickForceGradient(const ModeSet& m, int i, ConstState z, StateOut g) const override;
  double StaticLimit(int i, ConstState) const override { return p_.blocks[i].law.mu_s; }
  /// Moves x_i alone onto the limit (the holding force is affine in it).
  void ProjectOnExit(const ModeSet& m, int i, double bound, StateOut z) const override;

  void Field(const ModeSet& m, ConstState z, StateOut f) const override;
  void Jacobian(const ModeSet& m, ConstState z, MatrixOut J) const override;
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const override;
  /// x_i of steady sliding with every block slipping below: K x = mu(v),
  /// K the tridiagonal stiffness (Thomas' algorithm); false if K is singular.
  bool RestPositions(double* x) const;
  /// Steady sliding of the mode where every block slips below: K x = mu(v)
  /// with K the stiffness matrix, x' = 0; stable when J's eigenvalues are.
  bool Rest(const ModeSet& m, StateOut z, bool* stable) const override;

  /// "v", "kc", "beta" (every c_i = 2 beta), then "m<i>", "c<i>", "k<i>",
  /// "mu_s<i>" for i = 1..N.
  int parameters() const override { return 3 + 4 * blocks(); }
  std::string ParameterName(int j) const override;
  // kc with one block: it couples no neighbours (the block's field does not depend on it).
  std::string ParameterError(int j) const override;
  double ParameterValue(int j) const override;
  void SetParameterValue(int j, double value) override;

  /// The slip force of block i in slip mode `m` at velocity xd, the mode's
  /// branch extended across x' = v, and its slope dF/dx'.
  double SlipForce(int i, Mode m, double xd) const;
  double SlipForceSlope(int i, Mode m, double xd) const;

 private:
  void Rebuild();
  ChainParams p_;
  std::vector<Friction> friction_;
};

}  // namespace stickslip::chain
