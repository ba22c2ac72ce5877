// The modes of a friction system: each contact slips below its surface,
// sticks on it, or slips above (seed regions Omega_-, Omega, Omega_+ for one
// contact); a system with k contacts is in one mode per contact, a ModeSet
// (docs/theory.md, "One core"; Filippov 1988, ch. 2; Leine & Nijmeijer 2004).
#pragma once

#include <cstdint>
#include <string>

#include "stickslip/names.hpp"

namespace stickslip {

/// The state of one contact (seed eqs. 3.6-3.8).
enum class Mode : std::uint8_t {
  kSlipBelow,  // relative velocity h < 0: region Omega_- of the seed, eq. (3.7)
  kStick,      // h = 0 and the stick force within its static limit: Omega, eq. (3.6)
  kSlipAbove,  // h > 0: region Omega_+, eq. (3.8)
};
template <>
struct EnumNames<Mode> {
  static constexpr NamedValue<Mode> kTable[] = {
      {Mode::kSlipBelow, "slip-below"},
      {Mode::kStick, "stick"},
      {Mode::kSlipAbove, "slip-above"},
  };
};

/// One Mode per contact, for up to kMaxContacts contacts; a value type of
/// fixed size (no allocation), compared and copied as two bit sets.
class ModeSet {
 public:
  static constexpr int kMaxContacts = 256;
  /// Every contact slips below.
  ModeSet() = default;
  /// Contact 0 in mode m, the others below (a one-contact system's mode).
  explicit ModeSet(Mode m) { set(0, m); }

  Mode operator[](int i) const {
    if (Bit(stick_, i)) return Mode::kStick;
    return Bit(above_, i) ? Mode::kSlipAbove : Mode::kSlipBelow;
  }
  void set(int i, Mode m) {
    Put(stick_, i, m == Mode::kStick);
    Put(above_, i, m == Mode::kSlipAbove);
  }
  bool sticks(int i) const { return Bit(stick_, i); }
  /// Whether any contact sticks.
  bool AnySticks() const {
    for (std::uint64_t w : stick_)
      if (w) return true;
    return false;
  }
  /// The number of sticking contacts.
  int Sticking() const {
    int n = 0;
    for (std::uint64_t w : stick_) n += __builtin_popcountll(w);
    return n;
  }
  bool operator==(const ModeSet& o) const {
    for (int w = 0; w < kWords; ++w)
      if (stick_[w] != o.stick_[w] || above_[w] != o.above_[w]) return false;
    return true;
  }
  bool operator!=(const ModeSet& o) const { return !(*this == o); }

 private:
  static constexpr int kWords = kMaxContacts / 64;
  static bool Bit(const std::uint64_t* w, int i) { return (w[i >> 6] >> (i & 63)) & 1u; }
  static void Put(std::uint64_t* w, int i, bool on) {
    const std::uint64_t b = std::uint64_t{1} << (i & 63);
    w[i >> 6] = on ? (w[i >> 6] | b) : (w[i >> 6] & ~b);
  }
  std::uint64_t stick_[kWords] = {};
  std::uint64_t above_[kWords] = {};
};

/// The printed name of a mode of `contacts` contacts: Name for one
/// contact, else the contacts' names joined by ',' ("stick,slip-below").
std::string ModeSetName(const ModeSet& m, int contacts);

}  // namespace stickslip
