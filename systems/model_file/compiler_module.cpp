// The symbolic compiler as a loadable module, the apps' way to it
// (compile_loaded.cpp). Two C entries: the build it came from, and Compile.
// No exception crosses the module's edge: an error comes back as its text.
#include <exception>
#include <memory>
#include <string>

#include "model_file/compiled.hpp"
#include "model_file/model_spec.hpp"
#include "stickslip/version.hpp"

namespace mf = stickslip::model_file;

extern "C" __attribute__((visibility("default"))) const char* stickslip_model_compiler_build() {
  return stickslip::VersionString();
}

extern "C" __attribute__((visibility("default"))) int stickslip_model_compile(
    const mf::ModelSpec* spec, std::shared_ptr<const mf::Compiled>* out, std::string* error) {
  try {
    *out = mf::Compile(*spec);
    return 0;
  } catch (const std::exception& e) {
    *error = e.what();
  } catch (...) {
    *error = spec->source + ": the model compiler failed";
  }
  return 1;
}
