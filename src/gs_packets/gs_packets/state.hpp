// gs_packets/state.hpp — the GS state blob of a dump (PCSX2 `GSState::Freeze`), version 8 layout.
//
// Read with the search tool from PCSX2 `pcsx2/GS/GSState.cpp` `GSState::Freeze` and
// `GSState::GetSaveStateSize()` (the 2023 form without a version parameter): u32 version; the
// environment PRIM, PRMODECONT, TEXCLUT, SCANMSK, TEXA, FOGCOL, DIMX, DTHE, COLCLAMP, PABE, BITBLTBUF,
// TRXDIR, TRXPOS, TRXREG, TRXREG (obsolete copy), u64 each; per context (×2) XYOFFSET, TEX0, TEX1,
// CLAMP, MIPTBP1, MIPTBP2, SCISSOR, ALPHA, TEST, FBA, FRAME, ZBUF; then RGBAQ, ST, UV, FOG, XYZ, one
// obsolete GIFReg (u64); tr.x, tr.y (int); the 4 MiB memory; 4 GIF paths (GIFTag 16 bytes + reg u32);
// Q (float). `GSState::Defrost` reads versions <= 6 with an extra PRMODE after PRIM and TEX2 after
// TEX1, and versions <= 4 with 7 more u32 per context: those older layouts are not decoded here.
// Other versions (state_layout below): `GSState::Defrost` of the same source reads versions 7 and 8
// with this layout, versions <= 6 with an extra PRMODE after PRIM and TEX2 after TEX1 in each context,
// and versions <= 4 with 7 more u32 after each context's ZBUF. Version 9: PCSX2's newest `GSState.h`
// (2026 sources) has STATE_VERSION = 9 and a `GetSaveStateSize(int version)`, whose GSState.cpp was
// not found with the search tool; Arntzen-Software's parallel-gs renderer for PCSX2
// (`GSRendererPGS::Freeze` / `Defrost`, read with the search tool) writes version 8 ("v9 doesn't add
// anything meaningful for us") and reads a version-9 blob as version 8 except that after tr.x / tr.y
// it skips GetSaveStateSize(9) − GetSaveStateSize(8) bytes ("dummy transfer params") before the
// memory; its Freeze says "v9 adds a lot more dummy stuff here". So a version-9 blob is decoded here as
// version 8 with an opaque block of (blob size − 4194760) bytes, "v9_transfer", between tr.y and the
// memory: its size is taken from the blob, its contents are not decoded (PCSX2's field list for it
// was not read). gsdot3 writes version 8.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace gs::dump {

inline constexpr std::uint32_t state_version_written = 8;
inline constexpr std::uint32_t memory_bytes = 4u * 1024 * 1024;

struct state_field {
  std::string_view name;
  std::uint32_t offset, size;
};

namespace detail {
inline constexpr std::string_view env_names[] = {"PRIM",      "PRMODECONT", "TEXCLUT", "SCANMSK",  "TEXA",
                                                 "FOGCOL",    "DIMX",       "DTHE",    "COLCLAMP", "PABE",
                                                 "BITBLTBUF", "TRXDIR",     "TRXPOS",  "TRXREG",   "TRXREG_obsolete"};
inline constexpr std::string_view ctx_names[2][12] = {
    {"XYOFFSET_1", "TEX0_1", "TEX1_1", "CLAMP_1", "MIPTBP1_1", "MIPTBP2_1", "SCISSOR_1", "ALPHA_1", "TEST_1", "FBA_1",
     "FRAME_1", "ZBUF_1"},
    {"XYOFFSET_2", "TEX0_2", "TEX1_2", "CLAMP_2", "MIPTBP1_2", "MIPTBP2_2", "SCISSOR_2", "ALPHA_2", "TEST_2", "FBA_2",
     "FRAME_2", "ZBUF_2"}};
inline constexpr std::string_view vertex_names[] = {"RGBAQ", "ST", "UV", "FOG", "XYZ", "obsolete"};
inline constexpr std::string_view path_names[4][2] = {
    {"path0.tag", "path0.reg"}, {"path1.tag", "path1.reg"}, {"path2.tag", "path2.reg"}, {"path3.tag", "path3.reg"}};

constexpr auto make_fields() {
  std::array<state_field, 1 + 15 + 24 + 6 + 2 + 1 + 8 + 1> f{};
  std::size_t i = 0;
  std::uint32_t at = 0;
  auto add = [&](std::string_view n, std::uint32_t size) {
    f[i++] = {n, at, size};
    at += size;
  };
  add("version", 4);
  for (auto n : env_names) add(n, 8);
  for (const auto& c : ctx_names)
    for (auto n : c) add(n, 8);
  for (auto n : vertex_names) add(n, 8);
  add("tr.x", 4);
  add("tr.y", 4);
  add("memory", memory_bytes);
  for (const auto& p : path_names) {
    add(p[0], 16);
    add(p[1], 4);
  }
  add("Q", 4);
  return f;
}
}  // namespace detail

// Every field of the version-8 blob with its offset and size, in Freeze order.
inline constexpr auto state_fields_v8 = detail::make_fields();
inline constexpr std::uint32_t state_size_v8 = state_fields_v8.back().offset + state_fields_v8.back().size;
// 4 + 15·8 + 24·8 + 6·8 + 2·4 = 372 bytes before the memory; 4 MiB; 4·(16 + 4) + 4 after it.
static_assert(state_size_v8 == 372 + memory_bytes + 84);
static_assert(state_size_v8 == 4194760);

constexpr std::optional<state_field> state_field_v8(std::string_view name) noexcept {
  for (const auto& f : state_fields_v8)
    if (f.name == name) return f;
  return std::nullopt;
}
inline constexpr std::uint32_t state_memory_offset_v8 = 372;
static_assert(state_field_v8("memory")->offset == state_memory_offset_v8);

// The fields of a blob of `version` and `size` bytes, in Freeze order, or none when the version's
// layout is not known (> 9) or the size does not fit it.
inline std::optional<std::vector<state_field>> state_layout(std::uint32_t version, std::size_t size) {
  if (version > 9) return std::nullopt;
  const std::size_t extra = version == 9 ? size - std::min<std::size_t>(size, state_size_v8) : 0;
  std::vector<state_field> out;
  std::uint32_t at = 0;
  auto add = [&](std::string_view n, std::size_t bytes) {
    out.push_back({n, at, static_cast<std::uint32_t>(bytes)});
    at += static_cast<std::uint32_t>(bytes);
  };
  for (const state_field& f : state_fields_v8) {
    if (f.name == "memory" && version == 9) add("v9_transfer", extra);
    add(f.name, f.size);
    if (version <= 6 && f.name == "PRIM") add("PRMODE", 8);
    if (version <= 6 && (f.name == "TEX1_1" || f.name == "TEX1_2")) add(f.name == "TEX1_1" ? "TEX2_1" : "TEX2_2", 8);
    if (version <= 4 && (f.name == "ZBUF_1" || f.name == "ZBUF_2"))
      add(f.name == "ZBUF_1" ? "obsolete_1" : "obsolete_2", 28);
  }
  if (at != size) return std::nullopt;
  return out;
}
inline const state_field* find_field(const std::vector<state_field>& fields, std::string_view name) {
  for (const auto& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

// A little-endian field of a blob (fields of up to 8 bytes).
inline std::uint64_t state_get(std::span<const std::uint8_t> blob, const state_field& f) {
  std::uint64_t v = 0;
  for (std::uint32_t b = 0; b < f.size && b < 8; ++b) v |= std::uint64_t{blob[f.offset + b]} << (8 * b);
  return v;
}
inline void state_set(std::span<std::uint8_t> blob, const state_field& f, std::uint64_t v) {
  for (std::uint32_t b = 0; b < f.size && b < 8; ++b) blob[f.offset + b] = static_cast<std::uint8_t>(v >> (8 * b));
}

// A zeroed version-8 blob: version 8, PRMODECONT.AC = 1 and Q = 1.0f (PCSX2's GSState constructor
// sets both), everything else 0.
inline std::vector<std::uint8_t> make_state_v8() {
  std::vector<std::uint8_t> blob(state_size_v8, 0);
  state_set(blob, *state_field_v8("version"), state_version_written);
  state_set(blob, *state_field_v8("PRMODECONT"), 1);
  state_set(blob, *state_field_v8("Q"), 0x3F800000u);
  return blob;
}

}  // namespace gs::dump
