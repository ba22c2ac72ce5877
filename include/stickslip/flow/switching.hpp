// The flow's switching rules, one for every system (flow.hpp): Filippov's
// rule at an arrival on a contact's surface, and the one saltation formula
// (Leine & Nijmeijer 2004, section 7.3; di Bernardo et al. 2008, section 2.5).
#pragma once

#include <vector>

#include "stickslip/names.hpp"
#include "stickslip/system/system.hpp"

namespace stickslip {

/// How the mode of contacts that switch at one instant was found.
enum class ModeChoice {
  kUnique,        ///< exactly one consistent candidate
  kAmbiguous,     ///< several consistent candidates (mode: the first)
  kInconsistent,  ///< none (mode: the contact-order rule's)
  kTooMany,       ///< more than kMaxEnumeratedAfterCycle, pivoting cycled (mode: contact order)
  kPivoted,       ///< more than kMaxEnumeratedContacts: the consistent set pivoting found
};
template <>
struct EnumNames<ModeChoice> {
  static constexpr NamedValue<ModeChoice> kTable[] = {
      {ModeChoice::kUnique, "unique"},
      {ModeChoice::kAmbiguous, "ambiguous"},
      {ModeChoice::kInconsistent, "inconsistent"},
      {ModeChoice::kTooMany, "too-many"},
      {ModeChoice::kPivoted, "pivoted"},
  };
};
/// A choice the flow takes: the one consistent set, or the one pivoting found.
inline bool Resolved(ModeChoice c) { return c == ModeChoice::kUnique || c == ModeChoice::kPivoted; }

/// At most this many contacts are enumerated at once (3^8 candidates); more
/// are resolved by pivoting (PivotedMode), and where pivoting cycles, up to
/// kMaxEnumeratedAfterCycle (3^12 candidates) are enumerated after all.
constexpr int kMaxEnumeratedContacts = 8;
constexpr int kMaxEnumeratedAfterCycle = 12;

struct ModeChoiceResult {
  ModeChoice choice = ModeChoice::kUnique;
  ModeSet mode;
  int candidates = 0;  ///< contacts enumerated or pivoted
  int consistent = 0;  ///< consistent candidates found (pivoted: 1, the one it stopped at)
};

/// The consistent mode after the contacts `on` (each on its surface h_i = 0
/// at z) switch at one instant, the others keeping their modes of `base`
/// (Filippov's rule for several contacts; docs/theory.md, "Modes as sets").
/// Each candidate gives every contact of `on` stick, slip-below or
/// slip-above; it is consistent when every sticking contact has |lambda_i|
/// <= StaticLimit_i and every slipping one, held in stick, would need
/// |lambda_j| > StaticLimit_j pointing to its side (lambda_j > 0: below).
/// A sticking contact outside `on` whose lambda leaves its limit in the
/// chosen mode joins the candidates and the enumeration is repeated. One
/// contact alone gives ModeAfterArrival's mode. More than
/// kMaxEnumeratedContacts contacts are resolved by PivotedMode instead.
ModeChoiceResult ConsistentMode(const System& s, const ModeSet& base, std::vector<int> on,
                                ConstState z);

/// The consistency conditions of ConsistentMode solved by least-index
/// pivoting (Murty 1974's rule for the LCP, on the three modes of each
/// contact; docs/theory.md, "Modes as sets"): from every contact of `on`
/// stuck, the lowest contact whose mode is not consistent takes the mode its
/// force points to, until none is left: kPivoted with that set, whether or
/// not another consistent set exists. A set met twice, or more flips than
/// 3 q^2 + 3 for q contacts, is kTooMany with the last set (which need not
/// be consistent; a set may exist all the same).
ModeChoiceResult PivotedMode(const System& s, const ModeSet& base, const std::vector<int>& on,
                             ConstState z);

/// Mode m at a start z, with every sticking contact that sits on its static
/// limit (to kEventRounding) while the stick force moves out,
/// d/dt (|lambda_i| - StaticLimit_i) > 0 in m's field, released the way
/// lambda_i points: its exit lies at t = 0, where a root is no event
/// (Filippov's rule at the band's edge; the flow applies it to every start).
ModeSet ReleasedAtEdge(const System& s, ModeSet m, ConstState z);

/// ModeOf with how the contacts on their surfaces were resolved.
ModeChoiceResult ModeChoiceOf(const System& s, const Eigen::VectorXd& z);

/// The mode after contact c of mode `before` arrives on h_c = 0 at z: stick
/// while |lambda_c| <= StaticLimit_c (Filippov sliding), else slip the way
/// lambda_c points (a crossing, or a touch when that is the side it came from).
ModeSet ModeAfterArrival(const System& s, const ModeSet& before, int c, ConstState z);

/// grad h_c (n entries): the contact's relative velocity's gradient.
void ContactGradient(const System& s, int c, StateOut grad);
/// The gradient of a linear functional (n entries; a contact's velocity or a section).
void SurfaceGradient(const ContactVelocity& h, StateOut grad);
/// Puts z on h = 0: exactly where one component carries h (weight +-1),
/// else by the least-norm step along its weights.
void OntoSurface(const ContactVelocity& h, StateOut z);
/// Every contact that sticks in m onto its surface (a stick phase holds h = 0).
void OntoStickSurfaces(const System& s, const ModeSet& m, StateOut z);

/// d g / dp_j of contact c's stick exit g = lambda_c - sign StaticLimit_c
/// (mode `stick` has c sticking; sign +1 into slip below) at z.
double ExitParameterDerivative(const System& s, const ModeSet& stick, int c, int sign, int j,
                               ConstState z);

/// The saltation matrix of an event g = 0 (gradient grad, n entries) where
/// the field switches from mode `before` to `after` at z, on the tangent
/// block: S = I + (f+ - f-) grad^T / (grad . f-). False (S = I) where the
/// flow meets the surface tangentially (grad . f- = 0): no finite S.
bool Saltation(const System& s, const ModeSet& before, const ModeSet& after, ConstState z,
               ConstState grad, MatrixOut S);

}  // namespace stickslip
