// gs_cost/cost_json.hpp — the cost model's results as JSON, one form for `gsdot3 cost --json` and the
// report's "ps2" entries: cycles with their time at 147.456 MHz and NTSC / PAL budget, where they go,
// the counts behind them, each pass's drawing mode in words, and the options the prices came from.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "gs_cost/model.hpp"

namespace gs::cost {

nlohmann::json to_json(const breakdown& b);
nlohmann::json to_json(const tally& t);
nlohmann::json to_json(const cost_options& o);
// cycles, seconds, fps_unlocked and per video standard its budget share and locked fps.
nlohmann::json timing_json(std::uint64_t cycles);
// A frame: timing_json of its total, breakdown, counts, fill_rate_share (pixel cycles of all), the
// pass count, and every pass (timing, first_offset, mode, breakdown, counts, frame_share) when
// `with_passes`.
nlohmann::json frame_json(const frame_cost& f, bool with_passes);
// A pass's drawing mode: "TRIANGLE PSMCT32 tex PSMT8 bilinear blend Zrw", or "transfers only".
std::string mode_text(const pass_cost& p);
// Option values as their names: "blocks" / "pixels", "page" / "quarter_page".
std::string name(pixel_walk w);
std::string name(texture_unit u);

}  // namespace gs::cost
