// tests/gs_memory/formats.hpp — the storage formats and layouts the tests sweep.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gs_memory/format.hpp"

namespace gs::mem::test {

inline constexpr std::array all_psms = {psm::PSMCT32, psm::PSMCT24, psm::PSMCT16, psm::PSMCT16S, psm::PSMT8,
                                        psm::PSMT8H,  psm::PSMT4,   psm::PSMT4HL, psm::PSMT4HH,  psm::PSMZ32,
                                        psm::PSMZ24,  psm::PSMZ16,  psm::PSMZ16S};
inline constexpr std::array all_layouts = {layout::ct32, layout::z32,  layout::ct16, layout::ct16s,
                                           layout::z16,  layout::z16s, layout::t8,   layout::t4};

inline const char* name(layout l) {
  constexpr const char* names[] = {"ct32", "z32", "ct16", "ct16s", "z16", "z16s", "t8", "t4"};
  return names[static_cast<int>(l)];
}

// Pixel i of host transfer data, unpacked by hand: 4-bit formats low nibble first, 24-bit in 3 bytes.
inline std::uint32_t unpack(const std::vector<std::uint8_t>& d, unsigned bits, std::size_t i) {
  switch (bits) {
    case 4: return i % 2 == 0 ? d[i / 2] & 0xFu : d[i / 2] >> 4;
    case 8: return d[i];
    case 16: return d[2 * i] | d[2 * i + 1] << 8;
    case 24: return d[3 * i] | d[3 * i + 1] << 8 | d[3 * i + 2] << 16;
    default: return d[4 * i] | d[4 * i + 1] << 8 | d[4 * i + 2] << 16 | static_cast<std::uint32_t>(d[4 * i + 3]) << 24;
  }
}

}  // namespace gs::mem::test
