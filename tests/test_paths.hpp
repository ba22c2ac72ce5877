// Where the tests find the built apps and the shipped studies (both set by
// tests/CMakeLists.txt), shared so that the test files of one program can be
// compiled together (unity build).
#pragma once

#include <string>

inline const std::string kBin = STICKSLIP_BIN_DIR;
inline const std::string kStudies = STICKSLIP_SOURCE_DIR "/studies";
