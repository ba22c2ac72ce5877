// --study's value as a file: a path (it has a '/' or names a file) as given;
// a name (seed, seed.ini) from the first of StudyDirectories() that has it:
// $STICKSLIP_STUDIES (colon-separated), <app's dir>/../share/stickslip/studies,
// the install prefix's and the source tree's studies/.
#pragma once

#include <string>
#include <vector>

namespace stickslip::cli {

std::string FindStudy(const std::string& name);
std::vector<std::string> StudyDirectories();

}  // namespace stickslip::cli
