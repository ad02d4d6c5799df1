// gs_packets/state.hpp — the GS state blob of a dump: what PCSX2's `GSState::Freeze` writes.
//
// Read with the search tool (facts, not code); docs/dumps.md gives the table and the sources in full:
// - field order: `GSState::Freeze`, `GSState::Defrost` and `GSState::GetSaveStateSize(int version)`,
//   pcsx2/GS/GSState.cpp. The upstream copy stored (PCSX2/pcsx2) is the 2022-2023 one without a
//   version parameter (versions 7 and 8 alike); the version-9 form was read in the fork
//   TJnotJT/pcsx2 (2026 sources, commit 00b6e9a4): after tr.x, tr.y it writes m_tr's w, h, m_blit,
//   m_pos, m_reg, rect, total, start, end, write ("Version 9 up"), and Defrost reads them only for
//   version >= 9. Defrost reads versions <= 6 with PRMODE after PRIM and TEX2 after each TEX1, and
//   versions <= 4 with 7 u32 more after each context's ZBUF.
// - sizes: pcsx2/GS/GSRegs.h (#pragma pack(1); every GIFReg* register a REG64 union of u64, 8 bytes;
//   GIFTag a REG128, 16; the GIFReg set 8; GIFPath {GIFTag tag; ...; u32 reg; ...}; VM_SIZE 4194304);
//   pcsx2/GS/Renderers/Common/GSVertex.h (GSVertex: GIFRegST ST, GIFRegRGBAQ RGBAQ, GIFRegXYZ XYZ,
//   u32 UV, u32 FOG; static_assert 32 bytes): m_v.UV and m_v.FOG are 4 bytes; pcsx2/GS/GSState.h
//   (STATE_VERSION 9; GSTransferBuffer m_tr {int x, y, w, h, start, end, total; GSVector4i rect;
//   GIFRegBITBLTBUF m_blit; GIFRegTRXPOS m_pos; GIFRegTRXREG m_reg; bool write}; float m_q).
// Version 8 is 4194752 bytes, version 9 61 more. gsdot3 before issue 57 wrote version 8 with UV and
// FOG as 8 bytes each (4194760 bytes): read still, as that layout, recognised by its size.
#pragma once

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
struct freeze_item {
  std::string_view name;
  std::uint32_t size;
  std::uint32_t since = 0;  // the first version that writes it
};
// The fields Freeze writes, in order, with their sizeof.
inline constexpr freeze_item freeze_items[] = {
    {"version", 4},  // u32 STATE_VERSION
    // m_env: GIFRegPRIM ... GIFRegTRXREG, and TRXREG again ("obsolete")
    {"PRIM", 8},
    {"PRMODECONT", 8},
    {"TEXCLUT", 8},
    {"SCANMSK", 8},
    {"TEXA", 8},
    {"FOGCOL", 8},
    {"DIMX", 8},
    {"DTHE", 8},
    {"COLCLAMP", 8},
    {"PABE", 8},
    {"BITBLTBUF", 8},
    {"TRXDIR", 8},
    {"TRXPOS", 8},
    {"TRXREG", 8},
    {"TRXREG_obsolete", 8},
    // m_env.CTXT[0], CTXT[1]
    {"XYOFFSET_1", 8},
    {"TEX0_1", 8},
    {"TEX1_1", 8},
    {"CLAMP_1", 8},
    {"MIPTBP1_1", 8},
    {"MIPTBP2_1", 8},
    {"SCISSOR_1", 8},
    {"ALPHA_1", 8},
    {"TEST_1", 8},
    {"FBA_1", 8},
    {"FRAME_1", 8},
    {"ZBUF_1", 8},
    {"XYOFFSET_2", 8},
    {"TEX0_2", 8},
    {"TEX1_2", 8},
    {"CLAMP_2", 8},
    {"MIPTBP1_2", 8},
    {"MIPTBP2_2", 8},
    {"SCISSOR_2", 8},
    {"ALPHA_2", 8},
    {"TEST_2", 8},
    {"FBA_2", 8},
    {"FRAME_2", 8},
    {"ZBUF_2", 8},
    // m_v (GSVertex): RGBAQ, ST, u32 UV, u32 FOG, XYZ; then sizeof(GIFReg) skipped ("obsolite")
    {"RGBAQ", 8},
    {"ST", 8},
    {"UV", 4},
    {"FOG", 4},
    {"XYZ", 8},
    {"obsolete", 8},
    {"tr.x", 4},
    {"tr.y", 4},
    // version 9 on: the rest of m_tr
    {"tr.w", 4, 9},
    {"tr.h", 4, 9},
    {"tr.m_blit", 8, 9},
    {"tr.m_pos", 8, 9},
    {"tr.m_reg", 8, 9},
    {"tr.rect", 16, 9},
    {"tr.total", 4, 9},
    {"tr.start", 4, 9},
    {"tr.end", 4, 9},
    {"tr.write", 1, 9},
    {"memory", memory_bytes},  // m_mem.m_vm8, m_vmsize bytes
    {"path0.tag", 16},
    {"path0.reg", 4},
    {"path1.tag", 16},
    {"path1.reg", 4},  // m_path[4]: GIFTag, u32 reg
    {"path2.tag", 16},
    {"path2.reg", 4},
    {"path3.tag", 16},
    {"path3.reg", 4},
    {"Q", 4}};  // float m_q
constexpr std::size_t field_count(std::uint32_t version) {
  std::size_t n = 0;
  for (const auto& i : freeze_items) n += i.since <= version;
  return n;
}
template <std::uint32_t Version>
constexpr auto make_fields() {
  std::array<state_field, field_count(Version)> f{};
  std::size_t k = 0;
  std::uint32_t at = 0;
  for (const auto& i : freeze_items) {
    if (i.since > Version) continue;
    f[k++] = {i.name, at, i.size};
    at += i.size;
  }
  return f;
}
}  // namespace detail

// Every field of the version-8 (and 7) and the version-9 blob with its offset and size, in Freeze order.
inline constexpr auto state_fields_v8 = detail::make_fields<8>();
inline constexpr auto state_fields_v9 = detail::make_fields<9>();
inline constexpr std::uint32_t state_size_v8 = state_fields_v8.back().offset + state_fields_v8.back().size;
inline constexpr std::uint32_t state_size_v9 = state_fields_v9.back().offset + state_fields_v9.back().size;
// What gsdot3 wrote before issue 57: version 8 with UV and FOG as 8 bytes each.
inline constexpr std::uint32_t state_size_gsdot3_v8 = state_size_v8 + 8;

constexpr std::optional<state_field> state_field_v8(std::string_view name) noexcept {
  for (const auto& f : state_fields_v8)
    if (f.name == name) return f;
  return std::nullopt;
}

// The fields of a blob of `version` and `size` bytes, in Freeze order, or none when the version's
// layout is not known (> 9) or the size does not fit it. A version-8 blob of state_size_gsdot3_v8
// bytes is gsdot3's older layout.
inline std::optional<std::vector<state_field>> state_layout(std::uint32_t version, std::size_t size) {
  if (version > 9) return std::nullopt;
  const bool gsdot3_v8 = version == 8 && size == state_size_gsdot3_v8;
  std::vector<state_field> out;
  std::uint32_t at = 0;
  auto add = [&](std::string_view n, std::uint32_t bytes) {
    out.push_back({n, at, bytes});
    at += bytes;
  };
  for (const auto& i : detail::freeze_items) {
    if (i.since > version) continue;
    add(i.name, gsdot3_v8 && (i.name == "UV" || i.name == "FOG") ? 8 : i.size);
    if (version <= 6 && i.name == "PRIM") add("PRMODE", 8);
    if (version <= 6 && (i.name == "TEX1_1" || i.name == "TEX1_2")) add(i.name == "TEX1_1" ? "TEX2_1" : "TEX2_2", 8);
    if (version <= 4 && (i.name == "ZBUF_1" || i.name == "ZBUF_2"))
      add(i.name == "ZBUF_1" ? "obsolete_1" : "obsolete_2", 28);
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

// A zeroed blob of version 7, 8 or 9: the version, PRMODECONT.AC = 1 and Q = 1.0f (PCSX2's GSState
// constructor sets both), everything else 0 (version 9's m_tr fields included, as GSTransferBuffer
// initialises them).
inline std::vector<std::uint8_t> make_state(std::uint32_t version) {
  const auto size = version >= 9 ? state_size_v9 : state_size_v8;
  const auto fields = state_layout(version, size).value();
  std::vector<std::uint8_t> blob(size, 0);
  state_set(blob, *find_field(fields, "version"), version);
  state_set(blob, *find_field(fields, "PRMODECONT"), 1);
  state_set(blob, *find_field(fields, "Q"), 0x3F800000u);
  return blob;
}
// The blob gsdot3 writes (src/pipeline, src/probe).
inline std::vector<std::uint8_t> make_state_v8() { return make_state(state_version_written); }

}  // namespace gs::dump
