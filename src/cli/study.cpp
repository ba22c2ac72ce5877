#include "cli/study.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/run_control.hpp"
#include "cli/study_path.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {

namespace {

bool IsKeyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

bool IsKey(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), IsKeyChar);
}

}  // namespace

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string Printable(const std::string& s) {
  const std::string::size_type end = s.find_last_not_of("\n\r");
  std::string out;
  for (std::string::size_type i = 0; end != std::string::npos && i <= end; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      static const char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// ---------------------------------------------------------------------------
// Arguments

bool Arguments::Given(const std::string& name) const {
  const auto it = vm_.find(name);
  return it != vm_.end() && !it->second.empty() && !it->second.defaulted();
}

bool Arguments::OnCommandLine(const std::string& name) const {
  return Given(name) && origin_.find(name) == origin_.end();
}

std::string Arguments::Source(const std::string& name) const {
  const auto it = origin_.find(name);
  if (it != origin_.end()) return name + " (" + it->second + ")";
  return "--" + name;
}

std::string Arguments::Origin(const std::string& name) const {
  const auto it = origin_.find(name);
  return it != origin_.end() ? it->second : "--" + name;
}

std::string Arguments::Text(const std::string& name, const std::string& fallback) const {
  const auto it = vm_.find(name);
  if (it == vm_.end() || it->second.empty()) return fallback;
  return it->second.as<std::string>();
}

double Arguments::Number(const std::string& name, double fallback) const {
  const auto x = OptionalNumber(name);
  return x ? *x : fallback;
}

std::optional<double> Arguments::OptionalNumber(const std::string& name) const {
  if (!Given(name)) return std::nullopt;
  return ParseNumber(Text(name), Source(name));
}

long Arguments::Integer(const std::string& name, long fallback) const {
  if (!Given(name)) return fallback;
  const std::string text = Text(name);
  long value = 0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, value);
  if (text.empty() || r.ec != std::errc() || r.ptr != end)
    throw UsageError("invalid value '" + text + "' for " + Source(name) + ": not an integer");
  return value;
}

long Arguments::IntegerIn(const std::string& name, long fallback, long lo, long hi) const {
  const long n = Integer(name, fallback);
  if (n < lo || n > hi)
    throw UsageError("invalid value '" + Text(name) + "' for " + Source(name) + ": must be in [" +
                     std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return n;
}

bool Arguments::Flag(const std::string& name) const {
  const auto it = vm_.find(name);
  return it != vm_.end() && !it->second.empty() && it->second.as<bool>();
}

double ParseNumber(const std::string& text, const std::string& what) {
  auto bad = [&](const std::string& why) {
    return UsageError("invalid value '" + text + "' for " + what + ": " + why);
  };
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-') ++begin;
  double x = 0;
  const auto r = std::from_chars(begin, end, x);
  if (r.ec == std::errc::result_out_of_range) throw bad("out of range");
  if (text.empty() || r.ec != std::errc() || r.ptr != end) throw bad("not a number");
  if (!std::isfinite(x)) throw bad("not a finite number");
  return x;
}

// ---------------------------------------------------------------------------
// Parsing

Arguments ParseArguments(int argc, const char* const argv[], const po::options_description& desc,
                         const std::string& section) {
  Arguments args;
  try {
    const auto style =
        po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv).options(desc).style(style).run();
    for (const auto& o : parsed.options) {
      if (o.position_key >= 0 || o.string_key.empty()) {
        const std::string token = o.original_tokens.empty() ? "" : o.original_tokens.front();
        throw UsageError("unexpected argument '" + token + "' (options are --name value)");
      }
    }
    po::store(parsed, args.vm_);
  } catch (const po::error& e) {
    throw UsageError(Printable(e.what()));
  }
  const bool info = args.vm_.count("help") || args.Flag("version");
  if (!info && args.Given("study"))
    ReadStudyFile(FindStudy(args.Text("study")), desc, section, args);
  try {
    po::notify(args.vm_);
  } catch (const po::error& e) {
    throw UsageError(Printable(e.what()));
  }
  return args;
}

namespace {

// Refuses what is no readable regular file of at most kMaxStudyBytes.
void CheckStudyFile(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
    throw UsageError("cannot read study file '" + path + "': " + std::strerror(errno));
  if (S_ISDIR(st.st_mode))
    throw UsageError("cannot read study file '" + path + "': it is a directory");
  if (!S_ISREG(st.st_mode))
    throw UsageError("cannot read study file '" + path +
                     "': not a regular file (FIFO, device or socket)");
  if (st.st_size > kMaxStudyBytes)
    throw UsageError("cannot read study file '" + path + "': " + std::to_string(st.st_size) +
                     " bytes, more than " + std::to_string(kMaxStudyBytes));
}

}  // namespace

void ReadStudyFile(const std::string& path, const po::options_description& desc,
                   const std::string& section, Arguments& args) {
  CheckStudyFile(path);
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read study file '" + path + "': " + std::strerror(errno));
  args.study_ = path;

  const auto& sections = StudySections();
  std::map<std::string, int> seen;  // key -> line
  std::string current;              // the current section, "" at top level
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string where = path + ":" + std::to_string(line);
    auto malformed = [&](const std::string& why) {
      return UsageError("study file " + where + ": " + why);
    };
    if (raw.find('\0') != std::string::npos)
      throw malformed("a NUL byte (column " + std::to_string(raw.find('\0') + 1) +
                      "): not a text file");
    if (line > kMaxStudyBytes) throw malformed("the file grew while it was read");
    const std::string text = Trim(raw.substr(0, raw.find('#')));
    if (text.empty()) continue;
    if (text.front() == '[') {
      const std::string name = text.back() == ']' ? Trim(text.substr(1, text.size() - 2)) : "";
      if (!IsKey(name)) throw malformed("malformed section header '" + text + "'");
      if (name != "system" && std::find(sections.begin(), sections.end(), name) == sections.end()) {
        std::string known;
        for (const auto& s : sections) known += s + ", ";
        known += "system";
        throw malformed("unknown section [" + name + "] (known: " + known + ")");
      }
      current = name;
      continue;
    }
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw malformed("expected 'key = value', got '" + text + "'");
    const std::string key = Trim(text.substr(0, eq));
    const std::string value = Trim(text.substr(eq + 1));
    if (!IsKey(key)) throw malformed("malformed key in '" + text + "'");
    if (value.empty()) throw malformed("key '" + key + "' has no value");
    if (current == "system") {  // the system's own names, checked once it is built
      const auto [it, fresh] = seen.emplace("[system]" + key, line);
      if (!fresh) throw malformed("key '" + key + "' repeats line " + std::to_string(it->second));
      args.settings_.push_back({key, value, where});
      continue;
    }
    if (!current.empty() && current != section) continue;  // another app's section
    if (key == "study" || key == "help" || key == "version")
      throw malformed("key '" + key + "' is not allowed in a study file");
    const po::option_description* d = desc.find_nothrow(key, false);
    if (d == nullptr || d->long_name() != key) throw malformed("unknown key '" + key + "'");
    const auto [it, fresh] = seen.emplace(key, line);
    if (!fresh) throw malformed("key '" + key + "' repeats line " + std::to_string(it->second));
    if (args.Given(key)) continue;  // the command line wins
    po::parsed_options one(&desc);
    po::option o;
    o.string_key = key;
    o.value.push_back(value);
    o.original_tokens = {key, value};
    one.options.push_back(o);
    try {
      po::store(one, args.vm_);
    } catch (const po::error& e) {
      throw malformed(Printable(e.what()));
    }
    args.origin_[key] = where;
  }
  if (in.bad()) throw UsageError("cannot read study file '" + path + "': read error");
}

// ---------------------------------------------------------------------------
// Printing

void PrintHelp(std::ostream& os, const std::string& usage, const po::options_description& desc,
               const std::string& notes) {
  os << "usage: " << usage << "\n" << desc << "\n";
  if (!notes.empty()) os << notes << (notes.back() == '\n' ? "" : "\n");
}

void PrintError(const std::string& prog, const std::string& message) {
  std::cerr << prog << ": error: " << Printable(message) << std::endl;
}

int ReportError(const std::string& prog, const std::exception& e) {
  PrintError(prog, e.what());
  const bool bad_input = dynamic_cast<const InvalidArgument*>(&e) != nullptr ||
                         dynamic_cast<const po::error*>(&e) != nullptr;
  return bad_input ? 2 : 1;
}

int RunApp(const std::string& prog, const std::function<int()>& body) {
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout is reported below, not fatal
  try {
    const int code = body();
    CheckStdout();
    return code;
  } catch (const std::exception& e) {
    return ReportError(prog, e);
  } catch (...) {
    PrintError(prog, "unknown exception");
    return 1;
  }
}

}  // namespace stickslip::cli
