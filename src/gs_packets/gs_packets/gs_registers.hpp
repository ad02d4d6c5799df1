// gs_packets/gs_registers.hpp — GS general-purpose register addresses (the A+D address byte) and names.
//
// Addresses from the GS User's Manual register map, as PCSX2 `pcsx2/GS/GSRegs.h` `enum GIF_A_D_REG`
// lists them (0x43 ALPHA_2 … 0x62 LABEL read with the search tool; the rest from the same enum).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace gs::packets {

struct gs_register_name {
  std::uint8_t address;
  std::string_view name;
};

inline constexpr gs_register_name gs_register_names[] = {
    {0x00, "PRIM"},      {0x01, "RGBAQ"},     {0x02, "ST"},         {0x03, "UV"},         {0x04, "XYZF2"},
    {0x05, "XYZ2"},      {0x06, "TEX0_1"},    {0x07, "TEX0_2"},     {0x08, "CLAMP_1"},    {0x09, "CLAMP_2"},
    {0x0A, "FOG"},       {0x0C, "XYZF3"},     {0x0D, "XYZ3"},       {0x14, "TEX1_1"},     {0x15, "TEX1_2"},
    {0x16, "TEX2_1"},    {0x17, "TEX2_2"},    {0x18, "XYOFFSET_1"}, {0x19, "XYOFFSET_2"}, {0x1A, "PRMODECONT"},
    {0x1B, "PRMODE"},    {0x1C, "TEXCLUT"},   {0x22, "SCANMSK"},    {0x34, "MIPTBP1_1"},  {0x35, "MIPTBP1_2"},
    {0x36, "MIPTBP2_1"}, {0x37, "MIPTBP2_2"}, {0x3B, "TEXA"},       {0x3D, "FOGCOL"},     {0x3F, "TEXFLUSH"},
    {0x40, "SCISSOR_1"}, {0x41, "SCISSOR_2"}, {0x42, "ALPHA_1"},    {0x43, "ALPHA_2"},    {0x44, "DIMX"},
    {0x45, "DTHE"},      {0x46, "COLCLAMP"},  {0x47, "TEST_1"},     {0x48, "TEST_2"},     {0x49, "PABE"},
    {0x4A, "FBA_1"},     {0x4B, "FBA_2"},     {0x4C, "FRAME_1"},    {0x4D, "FRAME_2"},    {0x4E, "ZBUF_1"},
    {0x4F, "ZBUF_2"},    {0x50, "BITBLTBUF"}, {0x51, "TRXPOS"},     {0x52, "TRXREG"},     {0x53, "TRXDIR"},
    {0x54, "HWREG"},     {0x60, "SIGNAL"},    {0x61, "FINISH"},     {0x62, "LABEL"},
};

constexpr std::optional<std::string_view> gs_register_name_of(std::uint8_t address) noexcept {
  for (const auto& r : gs_register_names)
    if (r.address == address) return r.name;
  return std::nullopt;
}

constexpr std::optional<std::uint8_t> gs_register_address(std::string_view name) noexcept {
  for (const auto& r : gs_register_names)
    if (r.name == name) return r.address;
  return std::nullopt;
}

namespace reg {
inline constexpr std::uint8_t PRIM = 0x00, RGBAQ = 0x01, ST = 0x02, UV = 0x03, XYZF2 = 0x04, XYZ2 = 0x05, FOG = 0x0A,
                              XYZF3 = 0x0C, XYZ3 = 0x0D, BITBLTBUF = 0x50, TRXPOS = 0x51, TRXREG = 0x52, TRXDIR = 0x53,
                              TEXFLUSH = 0x3F;
}  // namespace reg

}  // namespace gs::packets
