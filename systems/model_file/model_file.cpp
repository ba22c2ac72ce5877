// Reading a model file (model_file.hpp).
#include "model_file/model_file.hpp"

#include <fstream>
#include <sstream>

#include "model_file/compiled.hpp"
#include "model_file/model_spec.hpp"
#include "model_file/model_system.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::model_file {

std::unique_ptr<System> ParseModel(const std::string& text, const std::string& source) {
  const ModelSpec spec = ReadSpec(text, source);
  auto system = std::make_unique<ModelSystem>(Compile(spec));
  if (const std::string e = system->ValidationError(); !e.empty())
    throw InvalidArgument(source + ": " + e);
  return system;
}

std::unique_ptr<System> ReadModel(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidArgument(path + ": cannot read the model file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InvalidArgument(path + ": cannot read the model file");
  return ParseModel(text.str(), path);
}

}  // namespace stickslip::model_file
