// A friction system of the user's own, written down once in a model file
// (docs/model_files.md) and run exactly by every tool of the one core:
//
//   # the seed belt (Abdo & Abouelsoud 2011, eq. 3.5)
//   coordinates = x
//   parameter beta = 0.05
//   parameter v = 0.25
//   x'' = -2*beta*x' - x + F
//   contact F = x' - v
//   law F = mu_s - ...         (the friction coefficient at slip speed s >= 0)
//   static F = mu_s            (optional: the law at s = 0)
//   normal F = 1 - gamma*y     (optional: 1)
//
// The file is read and checked once: an unknown symbol, a missing or second
// equation, a contact velocity that is not linear in the state or depends on
// nothing, a force that enters its equations nonlinearly or does not act on
// its own contact, or a function that is not smooth (abs, sign, ...) is one
// InvalidArgument "<file>:<line>: <problem>". The equations, laws, stick
// forces, Jacobians and Taylor recurrences then come from the file itself
// (GiNaC differentiates; a tape of elementary operations carries the
// recurrences: tape.hpp). No compiler is needed at run time.
#pragma once

#include <memory>
#include <string>

#include "stickslip/system/system.hpp"

namespace stickslip::model_file {

/// The system of a model file's text; `source` names it in messages (a path).
std::unique_ptr<System> ParseModel(const std::string& text, const std::string& source);
/// The system of the model file at `path` (InvalidArgument if unreadable).
std::unique_ptr<System> ReadModel(const std::string& path);
/// The model's name (its `name = ...` line, else the file's stem), if `s`
/// was read from a model file; else empty.
std::string ModelName(const System& s);

}  // namespace stickslip::model_file
