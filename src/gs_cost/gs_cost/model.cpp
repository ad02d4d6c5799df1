// gs_cost/model.cpp — the cost model's prices and its pass / frame accounting (see model.hpp).
#include "gs_cost/model.hpp"

#include <cmath>

#include "gs_memory/local_memory.hpp"

namespace gs::cost {
namespace {

constexpr std::uint64_t ceil_div(std::uint64_t a, std::uint64_t b) noexcept { return (a + b - 1) / b; }

// The 1024-bit read and write buses (Sony spec, constants.hpp): 128 bytes per cycle each way.
constexpr std::uint64_t local_bus_bytes_per_cycle = 1024 / 8;

}  // namespace

breakdown& breakdown::operator+=(const breakdown& o) noexcept {
  pixels += o.pixels, page_breaks += o.page_breaks, texture_misses += o.texture_misses;
  uploads += o.uploads, clut_loads += o.clut_loads, setup += o.setup;
  return *this;
}

tally& tally::operator+=(const tally& o) noexcept {
  primitives += o.primitives, triangles += o.triangles, sprites += o.sprites, pixels += o.pixels, blocks += o.blocks;
  page_breaks += o.page_breaks, texture_misses += o.texture_misses, transfers += o.transfers;
  upload_bytes += o.upload_bytes, clut_loads += o.clut_loads;
  return *this;
}

double fps_unlocked(std::uint64_t cycles) noexcept {
  return cycles == 0 ? 0.0 : gs_clock_hz / static_cast<double>(cycles);
}

double fps_locked(std::uint64_t cycles, double hz) noexcept {
  if (cycles == 0) return hz;
  const double fields = std::ceil(seconds(cycles) * hz - 1e-12);
  return hz / std::max(1.0, fields);
}

std::uint64_t primitive_cycles(const draw_mode& m, const walk_counts& w, const cost_options& o) noexcept {
  const std::uint64_t setup = m.prim == 6 ? o.sprite_setup_cycles : triangle_setup_cycles;
  const std::uint64_t rate = m.textured ? pixels_per_cycle_textured : pixels_per_cycle_untextured;
  std::uint64_t pixel = o.walk == pixel_walk::blocks ? w.blocks : ceil_div(w.pixels, rate);
  if (m.blend_reads_dst) pixel *= std::max<std::uint32_t>(1, o.blend_rate_divisor);
  return setup + pixel + w.page_breaks * o.page_break_cycles + w.texture_misses * o.texture_miss_cycles;
}

std::uint64_t upload_cycles(std::uint64_t bytes) noexcept { return ceil_div(bytes, gif_bytes_per_cycle); }

std::uint64_t copy_cycles(std::uint64_t bytes) noexcept { return ceil_div(bytes, local_bus_bytes_per_cycle); }

std::uint64_t clut_load_cycles(std::uint32_t entries, const cost_options& o) noexcept {
  return ceil_div(std::uint64_t{entries} * 4, texture_bus_bytes_per_cycle) + o.clut_load_extra_cycles;
}

pass_cost& cost_model::open_pass(std::uint64_t offset) {
  current_.passes.push_back(pending_);
  pass_cost& p = current_.passes.back();
  if (!pending_any_) p.first_offset = offset;
  pending_ = {};
  pending_any_ = false;
  return p;
}

void cost_model::primitive(const packets::draw_registers& r, std::span<const packets::vertex> v, bool /*drawn*/,
                           std::uint64_t offset) {
  if (!pass_open_ || current_.passes.back().regs != r) {
    pass_cost& p = open_pass(offset);
    p.regs = r;
    p.mode = decode_mode(r);
    pass_open_ = true;
  } else if (pending_any_) {  // a transfer between primitives of one pass: charged to it
    pass_cost& p = current_.passes.back();
    p.counts += pending_.counts;
    p.cycles += pending_.cycles;
    pending_ = {};
    pending_any_ = false;
  }
  pass_cost& p = current_.passes.back();
  const walk_counts w = walk_primitive(r, v, pages_, opt_.texture_miss_unit);
  const std::uint64_t total = primitive_cycles(p.mode, w, opt_);
  breakdown b;
  b.setup = p.mode.prim == 6 ? opt_.sprite_setup_cycles : triangle_setup_cycles;
  b.page_breaks = w.page_breaks * opt_.page_break_cycles;
  b.texture_misses = w.texture_misses * opt_.texture_miss_cycles;
  b.pixels = total - b.setup - b.page_breaks - b.texture_misses;
  p.cycles += b;
  tally t;
  t.primitives = 1;
  (p.mode.prim == 6 ? t.sprites : t.triangles) = 1;
  t.pixels = w.pixels, t.blocks = w.blocks, t.page_breaks = w.page_breaks, t.texture_misses = w.texture_misses;
  p.counts += t;
}

void cost_model::transfer(const packets::completed_transfer& t, std::uint64_t bytes, bool local_to_local) {
  if (!pending_any_) pending_.first_offset = t.offset;
  pending_any_ = true;
  pending_.counts.transfers += 1;
  pending_.counts.upload_bytes += bytes;
  pending_.cycles.uploads += local_to_local ? copy_cycles(bytes) : upload_cycles(bytes);
}

void cost_model::clut_load(std::uint32_t entries, std::uint64_t offset) {
  if (!pending_any_) pending_.first_offset = offset;
  pending_any_ = true;
  pending_.counts.clut_loads += 1;
  pending_.cycles.clut_loads += clut_load_cycles(entries, opt_);
}

void cost_model::close_frame() {
  if (pending_any_) open_pass(pending_.first_offset);
  pass_open_ = false;
  if (current_.passes.empty()) return;
  for (const pass_cost& p : current_.passes) current_.counts += p.counts, current_.cycles += p.cycles;
  frames_.push_back(std::move(current_));
  current_ = {};
}

void cost_model::vsync(std::uint64_t /*offset*/) { close_frame(); }

const std::vector<frame_cost>& cost_model::finish() {
  close_frame();
  return frames_;
}

std::vector<frame_cost> price_dump(const dump::gs_dump& d, const cost_options& o, bool skip_unmodelled) {
  cost_model model(o);
  mem::local_memory m;
  packets::interpreter it(m, {.skip_unmodelled = skip_unmodelled, .observer = &model});
  it.replay(d);
  return model.finish();
}

}  // namespace gs::cost
