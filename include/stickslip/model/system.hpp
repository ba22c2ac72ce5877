// The model seam (issue 19, design.md section 2): what a flow, its events and
// its orbits need of a friction system. A system is a plain class (no virtual
// calls on the hot path) checked at compile time by IsFrictionSystem:
//   kStateSize                       state dimension (x, x') = 2; time t enters the fields
//   Field(mode, t, z)                each mode's vector field f(t, z) (slip, and stick)
//   Jacobian(mode, t, z)             df/dz of a slip mode
//   RelativeVelocity(z)              the contact's relative velocity x' - v: 0 on the
//                                    switching surface, negative in kSlipBelow
//   StickForce(t, x)                 the force that holds stick; stick holds while
//                                    |StickForce| <= static_limit()
//   StickForceRate(t)                its time derivative along the stick motion
//   ModeAfterArrival(from, t, x)     the Filippov rule on x' = v: stick, cross or stay
//   ExitMode(t, x)                   the slip mode a stick phase leaves into
// Taylor recurrences of each slip field live beside the stepper that uses
// them (src/forced/forced_taylor.hpp): they are the system's too, but they
// must inline into the stepper's loop.
#pragma once

#include <Eigen/Dense>
#include <type_traits>
#include <utility>

#include "stickslip/model/model.hpp"

namespace stickslip::model {

template <class S, class = void>
struct IsFrictionSystem : std::false_type {};

template <class S>
struct IsFrictionSystem<
    S, std::void_t<decltype(S::kStateSize),
                   decltype(std::declval<const S&>().Field(Mode{}, 0.0, std::declval<Vec2>())),
                   decltype(std::declval<const S&>().Jacobian(Mode{}, 0.0, std::declval<Vec2>())),
                   decltype(std::declval<const S&>().RelativeVelocity(std::declval<Vec2>())),
                   decltype(std::declval<const S&>().StickForce(0.0, 0.0)),
                   decltype(std::declval<const S&>().StickForceRate(0.0)),
                   decltype(std::declval<const S&>().static_limit()),
                   decltype(std::declval<const S&>().ModeAfterArrival(Mode{}, 0.0, 0.0)),
                   decltype(std::declval<const S&>().ExitMode(0.0, 0.0))>> : std::true_type {};

}  // namespace stickslip::model
