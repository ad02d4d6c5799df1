// cli/output_file.hpp — a command's output file, written atomically by pipeline::write_file_atomically
// (temporary name, then rename); a failure is the user's one-line error naming the option.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "pipeline/files.hpp"

namespace gsdot3::cli {

inline void write_output(const std::filesystem::path& file, std::string_view bytes, std::string_view option) {
  try {
    pipeline::write_file_atomically(file, bytes);
  } catch (const std::runtime_error& e) { throw usage_error(std::string(option) + ": " + e.what()); }
}

}  // namespace gsdot3::cli
