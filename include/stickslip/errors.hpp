// Misuse of the library is an exception; numerical outcomes are statuses.
// After Boost.Odeint's util/odeint_error.hpp: a tiny hierarchy.
#pragma once

#include <stdexcept>
#include <string>

namespace stickslip {

/// Base of every exception the library throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An argument the caller should have validated: an unknown parameter name,
/// a value out of range, an inconsistent option. The message names the value.
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

/// A third-party call (SUNDIALS, NLopt) failed in a way that is not a
/// numerical outcome (out of memory, bad set-up). The message names the call.
class ExternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace stickslip
