// --study NAME: a study file by name, found where the studies are installed
// (share/stickslip/studies beside the apps' bin/) or in the source tree.
#include "cli/study_path.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace stickslip::cli {

namespace {

bool IsFile(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The directory of the running app (Linux: /proc/self/exe), "" if unknown.
std::string ExeDir() {
  std::string buf(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return "";
  buf.resize(static_cast<size_t>(n));
  const auto slash = buf.rfind('/');
  return slash == std::string::npos ? "" : buf.substr(0, slash);
}

}  // namespace

std::vector<std::string> StudyDirectories() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("STICKSLIP_STUDIES")) {  // colon-separated
    std::string s = env;
    for (size_t b = 0; b <= s.size();) {
      const size_t e = std::min(s.find(':', b), s.size());
      if (e > b) dirs.push_back(s.substr(b, e - b));
      b = e + 1;
    }
  }
  const std::string exe = ExeDir();
  if (!exe.empty()) dirs.push_back(exe + "/../share/stickslip/studies");  // an install
#ifdef STICKSLIP_INSTALLED_STUDIES
  dirs.push_back(STICKSLIP_INSTALLED_STUDIES);
#endif
#ifdef STICKSLIP_SOURCE_STUDIES
  dirs.push_back(STICKSLIP_SOURCE_STUDIES);  // the build tree's apps
#endif
  return dirs;
}

std::string FindStudy(const std::string& name) {
  if (IsFile(name) || name.find('/') != std::string::npos) return name;  // a path: as given
  for (const std::string& dir : StudyDirectories())
    for (const std::string& file : {name, name + ".ini"})
      if (IsFile(dir + "/" + file)) return dir + "/" + file;
  return name;  // ReadStudyFile then says it cannot be read
}

}  // namespace stickslip::cli
