// The library's version: the one source of it. CMakeLists.txt reads it from
// here for the CMake package, `breakshot --version` prints it (with the
// commit the command was built from) and the page shows it (bs_version).
// CHANGELOG.md says what each version changed.
#pragma once

#include <string_view>

namespace breakshot {

inline constexpr std::string_view kVersion = "0.1.0";

}  // namespace breakshot
