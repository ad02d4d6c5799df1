// gs_cost/model.hpp — the GS cost model: an observer of the packet interpreter (gs_packets
// interpreter_observer) that prices every primitive, transfer and CLUT load of a dump as it is
// replayed, in GS cycles at 147.456 MHz (constants.hpp: the sources; docs/cost.md: the model).
//
// Per primitive: set-up (triangle_setup_cycles, or the sprite_setup_cycles option) + pixel cycles (the
// walk's blocks, or pixels / rate; the rate divided by blend_rate_divisor when the blend reads the
// destination) + page breaks × page_break_cycles + texture misses × texture_miss_cycles. Per host ->
// local transfer: bytes / 8 (the GIF's 64 bits per cycle), rounded up; local -> local copies are priced
// as one read and one write of their bytes over the 1024-bit buses (128 bytes per cycle each way, so
// bytes / 128). Per CLUT load: entries × 4 bytes / 64 per cycle, rounded up, + clut_load_extra_cycles.
// Terms add: the GS does one thing at a time in stream order; the GIF's delivery of the stream itself
// is not charged beyond the IMAGE data (it overlaps drawing through the GIF FIFO).
//
// A pass is a maximal run of consecutive primitives that draw with the same registers (every field of
// packets::draw_registers: PRIM with its type and attribute bits, FRAME, ZBUF, TEX0, TEX1, CLAMP,
// ALPHA, TEST, SCISSOR, XYOFFSET, FBA, TEXA, DIMX, DTHE, COLCLAMP, PABE, SCANMSK). Transfers and CLUT
// loads are charged to the pass they precede (the next primitive's); what no primitive follows before a
// vsync forms a pass of its own with no primitives. A frame is what lies between vsync packets.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gs_cost/constants.hpp"
#include "gs_cost/walk.hpp"
#include "gs_packets/interpreter.hpp"

namespace gs::cost {

// Cycles by where they go.
struct breakdown {
  std::uint64_t pixels = 0, page_breaks = 0, texture_misses = 0, uploads = 0, clut_loads = 0, setup = 0;
  constexpr std::uint64_t total() const noexcept {
    return pixels + page_breaks + texture_misses + uploads + clut_loads + setup;
  }
  breakdown& operator+=(const breakdown& o) noexcept;
  friend constexpr bool operator==(const breakdown&, const breakdown&) = default;
};

// Counts behind the cycles.
struct tally {
  std::uint64_t primitives = 0, triangles = 0, sprites = 0, pixels = 0, blocks = 0, page_breaks = 0, texture_misses = 0;
  std::uint64_t transfers = 0, upload_bytes = 0, clut_loads = 0;
  tally& operator+=(const tally& o) noexcept;
  friend constexpr bool operator==(const tally&, const tally&) = default;
};

struct pass_cost {
  std::uint64_t first_offset = 0;  // dump byte of the pass's first primitive (or transfer)
  packets::draw_registers regs{};  // what its primitives draw with (zero for a transfers-only pass)
  draw_mode mode{};
  tally counts{};
  breakdown cycles{};
};

struct frame_cost {
  std::vector<pass_cost> passes;
  tally counts{};
  breakdown cycles{};
};

// Seconds for a cycle count at the GS clock; frames per second when a frame takes `cycles`, unlocked
// (1 / seconds) and locked to the field rate `hz` (hz / the fields the frame spans, rounded up).
constexpr double seconds(std::uint64_t cycles) noexcept { return static_cast<double>(cycles) / gs_clock_hz; }
double fps_unlocked(std::uint64_t cycles) noexcept;
double fps_locked(std::uint64_t cycles, double hz) noexcept;

// Prices of the single events, as the model charges them (the tests check them against hand sums).
std::uint64_t primitive_cycles(const draw_mode& m, const walk_counts& w, const cost_options& o) noexcept;
std::uint64_t upload_cycles(std::uint64_t bytes) noexcept;
std::uint64_t copy_cycles(std::uint64_t bytes) noexcept;
std::uint64_t clut_load_cycles(std::uint32_t entries, const cost_options& o) noexcept;

class cost_model : public packets::interpreter_observer {
 public:
  explicit cost_model(cost_options o = {}) : opt_(o) {}

  void primitive(const packets::draw_registers& r, std::span<const packets::vertex> v, bool drawn,
                 std::uint64_t offset) override;
  void transfer(const packets::completed_transfer& t, std::uint64_t bytes, bool local_to_local) override;
  void clut_load(std::uint32_t entries, std::uint64_t offset) override;
  void vsync(std::uint64_t offset) override;

  // Closes the open frame (if it holds anything) and returns every frame.
  const std::vector<frame_cost>& finish();

 private:
  pass_cost& open_pass(std::uint64_t offset);
  void close_frame();

  cost_options opt_;
  page_state pages_{};
  std::vector<frame_cost> frames_;
  frame_cost current_{};
  pass_cost pending_{};  // transfers and CLUT loads waiting for the next primitive
  bool pending_any_ = false;
  bool pass_open_ = false;  // current_.passes.back() takes further primitives with its registers
};

// Replays a dump through the interpreter (into a scratch local memory) with a cost model attached;
// `skip_unmodelled` prices primitives the interpreter cannot draw too (they are priced either way; the
// flag only keeps the replay going). Throws what interpreter::replay throws.
std::vector<frame_cost> price_dump(const dump::gs_dump& d, const cost_options& o = {}, bool skip_unmodelled = true);

}  // namespace gs::cost
