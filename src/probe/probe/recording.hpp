// probe/recording.hpp — a probe screenshot as a recording file that `gsdot3 vectors ver` reads.
//
//   gsdot3-probe 1 frame=640x448 tfx_rounding=floor gouraud_fraction=keep_fraction ...   header
//   # gouraud_fraction: keep_fraction                                                     comments
//   gouraud_fraction.ramp 16 16 => 020202 020202 ... (36 fields)                          one patch
//
// The header names the probe format version, the frame size and every model option (the values
// the decoder found; the default where none matched or the option is not probed). Each patch line
// is the patch's name and cell (x, y), then its sampled pixels (the cell's inner 6×6, row by row) as
// observed, 0xRRGGBB in 6 hex digits (readers accept 1..6). Verifying re-renders the probe frame
// under the header's options (plus --option overrides) and compares every line (TestFloat-style
// report, vectors/verify.hpp).
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "gs_arith/options.hpp"
#include "probe/decode.hpp"
#include "vectors/verify.hpp"

namespace gsdot3::probe {

inline constexpr std::string_view recording_magic = "gsdot3-probe";
inline constexpr int recording_version = 1;

// The recording of `shot`, with the options `decoded` found (a value only where exactly one matched).
std::string write_recording(const rgb_frame& shot, const std::vector<verdict>& decoded);

// True when the first line that is not blank or a comment starts with recording_magic.
bool is_recording(std::string_view text);

// Throws vectors::format_error ("line N: ...") for a missing or bad header; bad patch lines are
// reported and counted as failures.
vectors::verify_result verify_recording(std::istream& in, std::ostream& report, const vectors::verify_settings& s);

}  // namespace gsdot3::probe
