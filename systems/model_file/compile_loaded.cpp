// Compile (compiled.hpp) in the apps: the symbolic compiler and GiNaC, CLN
// and GMP are a module (compiler_module.cpp) loaded when the first model file
// is read. Linked in, their static initialisers cost every app's start-up
// about 0.6 ms, model file or not (docs/benchmarks.md, "Process start-up").
// The module is looked for beside the executable (the build tree), then
// where `cmake --install` puts it relative to the executable.
#include <dlfcn.h>
#include <unistd.h>

#include <string>

#include "model_file/compiled.hpp"
#include "model_file/model_spec.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/version.hpp"

namespace stickslip::model_file {
namespace {

using Entry = int (*)(const ModelSpec*, std::shared_ptr<const Compiled>*, std::string*);
using Build = const char* (*)();

struct Module {
  Entry entry = nullptr;
  std::string error;  ///< why there is none
};

std::string ExecutableDir() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  const std::string path(buf, static_cast<std::size_t>(n));
  return path.substr(0, path.find_last_of('/'));
}

Module Open(const std::string& path) {
  void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) return {nullptr, dlerror()};
  const auto build = reinterpret_cast<Build>(dlsym(h, "stickslip_model_compiler_build"));
  const auto entry = reinterpret_cast<Entry>(dlsym(h, "stickslip_model_compile"));
  if (!build || !entry) return {nullptr, path + " is no stickslip model compiler"};
  if (std::string(build()) != VersionString())
    return {nullptr, path + " is stickslip " + build() + ", not " + VersionString()};
  return {entry, ""};  // never closed: the compiled models' deleters live in it
}

Module Load() {
  const std::string dir = ExecutableDir();
  Module m = Open(dir + "/" STICKSLIP_MODEL_MODULE);
  if (m.entry) return m;
  Module installed = Open(dir + "/" STICKSLIP_MODEL_MODULE_FROM_BIN "/" STICKSLIP_MODEL_MODULE);
  if (!installed.entry) installed.error = m.error + "; " + installed.error;
  return installed;
}

}  // namespace

std::shared_ptr<const Compiled> Compile(const ModelSpec& spec) {
  static const Module module = Load();  // once, thread-safe
  if (!module.entry)
    throw InvalidArgument(spec.source + ": cannot load the model compiler: " + module.error);
  std::shared_ptr<const Compiled> out;
  std::string error;
  if (module.entry(&spec, &out, &error) != 0) throw InvalidArgument(error);
  return out;
}

}  // namespace stickslip::model_file
