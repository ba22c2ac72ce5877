// Compile (compiled.hpp) in a program that links GiNaC itself: the library's
// users, the tests and Python call the symbolic compiler (compiler.hpp)
// directly. The apps load it as a module instead (compile_loaded.cpp).
#include "model_file/compiled.hpp"
#include "model_file/compiler.hpp"

namespace stickslip::model_file {

std::shared_ptr<const Compiled> Compile(const ModelSpec& spec) { return Compiler(spec).Run(); }

}  // namespace stickslip::model_file
