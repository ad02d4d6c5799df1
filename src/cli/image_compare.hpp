// cli/image_compare.hpp — per-pixel differences of two PNG frames, shared by `gsdot3 compare` and
// `gsdot3 replay --expect`: sizes must match; prints the counts per channel, the largest differences,
// a histogram of each pixel's largest channel difference, the first `first` differing pixels in hex,
// and writes a heat map PNG when `heat` is not empty. Returns the number of differing pixels; bad
// input throws cli::usage_error.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace gsdot3::cli {

// Throws usage_error "OPTION: FILE: why" unless FILE's header reads as a PNG of a size compare_pngs takes.
void check_png(const std::string& option, const std::string& file);

std::uint64_t compare_pngs(const std::string& a, const std::string& b, const std::string& heat, int first,
                           std::ostream& out);

}  // namespace gsdot3::cli
