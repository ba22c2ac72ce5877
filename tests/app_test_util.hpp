// Small file helpers shared by the end-to-end tests of the apps.
#pragma once

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace stickslip::testing_util {

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

inline bool Exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

inline void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A self-describing TSV (report.hpp): "# key: value" lines, then the header
// line (no '#'), then rows; read the way csv.DictReader reads it after the
// '#' lines are dropped.
struct Tsv {
  std::vector<std::string> comments;        // whole '#' lines
  std::map<std::string, std::string> meta;  // "# key: value" lines
  std::vector<std::string> columns;         // the first line without '#'
  std::vector<std::vector<std::string>> rows;
  int Column(const std::string& name) const {
    for (size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return static_cast<int>(i);
    return -1;
  }
};

inline std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream is(line);
  for (std::string cell; std::getline(is, cell, '\t');) cells.push_back(cell);
  if (!line.empty() && line.back() == '\t') cells.push_back("");
  return cells;
}

inline Tsv ReadTsv(const std::string& text) {
  Tsv t;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) {
    if (!line.empty() && line[0] == '#') {
      t.comments.push_back(line);
      const auto colon = line.find(": ");
      if (line.rfind("# ", 0) == 0 && colon != std::string::npos)
        t.meta[line.substr(2, colon - 2)] = line.substr(colon + 2);
    } else if (t.columns.empty()) {
      t.columns = SplitTabs(line);
    } else {
      t.rows.push_back(SplitTabs(line));
    }
  }
  return t;
}

}  // namespace stickslip::testing_util
