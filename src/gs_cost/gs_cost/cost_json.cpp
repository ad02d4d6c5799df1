// gs_cost/cost_json.cpp — see cost_json.hpp.
#include "gs_cost/cost_json.hpp"

#include "gs_memory/psm_names.hpp"
#include "gs_packets/draw.hpp"

namespace gs::cost {

namespace {

double share(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

nlohmann::json to_json(const breakdown& b) {
  return {{"pixels", b.pixels},   {"page_breaks", b.page_breaks}, {"texture_misses", b.texture_misses},
          {"uploads", b.uploads}, {"clut_loads", b.clut_loads},   {"setup", b.setup},
          {"total", b.total()}};
}

nlohmann::json to_json(const tally& t) {
  return {{"primitives", t.primitives},
          {"triangles", t.triangles},
          {"sprites", t.sprites},
          {"pixels", t.pixels},
          {"blocks", t.blocks},
          {"page_breaks", t.page_breaks},
          {"texture_misses", t.texture_misses},
          {"transfers", t.transfers},
          {"upload_bytes", t.upload_bytes},
          {"clut_loads", t.clut_loads}};
}

nlohmann::json to_json(const cost_options& o) {
  return {{"walk", name(o.walk)},
          {"page_break_cycles", o.page_break_cycles},
          {"texture_miss_cycles", o.texture_miss_cycles},
          {"texture_miss_unit", name(o.texture_miss_unit)},
          {"sprite_setup_cycles", o.sprite_setup_cycles},
          {"clut_load_extra_cycles", o.clut_load_extra_cycles},
          {"blend_rate_divisor", o.blend_rate_divisor}};
}

nlohmann::json timing_json(std::uint64_t cycles) {
  return {{"cycles", cycles},
          {"seconds", seconds(cycles)},
          {"ntsc", {{"budget_share", seconds(cycles) * ntsc_hz}, {"fps_locked", fps_locked(cycles, ntsc_hz)}}},
          {"pal", {{"budget_share", seconds(cycles) * pal_hz}, {"fps_locked", fps_locked(cycles, pal_hz)}}},
          {"fps_unlocked", fps_unlocked(cycles)}};
}

nlohmann::json frame_json(const frame_cost& f, bool with_passes) {
  const std::uint64_t total = f.cycles.total();
  nlohmann::json j = timing_json(total);
  j["breakdown"] = to_json(f.cycles);
  j["counts"] = to_json(f.counts);
  j["fill_rate_share"] = share(f.cycles.pixels, total);
  j["pass_count"] = f.passes.size();
  if (!with_passes) return j;
  j["passes"] = nlohmann::json::array();
  for (const pass_cost& p : f.passes) {
    nlohmann::json jp = timing_json(p.cycles.total());
    jp["first_offset"] = p.first_offset;
    jp["mode"] = mode_text(p);
    jp["breakdown"] = to_json(p.cycles);
    jp["counts"] = to_json(p.counts);
    jp["frame_share"] = share(p.cycles.total(), total);
    j["passes"].push_back(jp);
  }
  return j;
}

std::string mode_text(const pass_cost& p) {
  if (p.counts.primitives == 0) return "transfers only";
  const draw_mode& m = p.mode;
  std::string s = std::string(packets::prim_names[m.prim & 7]) + " " +
                  std::string(mem::name_of(static_cast<mem::psm>(m.frame_psm)));
  if (m.textured)
    s += " tex " + std::string(mem::name_of(static_cast<mem::psm>(m.tex_psm))) + (m.bilinear ? " bilinear" : "");
  if (m.blend_reads_dst) s += " blend";
  if (m.z_read || m.z_write) s += std::string(" Z") + (m.z_read ? "r" : "") + (m.z_write ? "w" : "");
  return s;
}

std::string name(pixel_walk w) { return w == pixel_walk::blocks ? "blocks" : "pixels"; }
std::string name(texture_unit u) { return u == texture_unit::page ? "page" : "quarter_page"; }

}  // namespace gs::cost
