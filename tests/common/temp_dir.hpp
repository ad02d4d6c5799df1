// tests/common/temp_dir.hpp — a fresh, uniquely named directory under the system's temp dir for one
// test (mkdtemp), so that concurrent runs of the suite (several build trees, ctest -j) never share
// files. The caller removes it when done; a failed test leaves it for inspection.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gsdot3::test {

inline std::filesystem::path fresh_temp_dir(std::string_view stem) {
  std::string pattern = (std::filesystem::temp_directory_path() / (std::string(stem) + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
  return pattern;
}

}  // namespace gsdot3::test
