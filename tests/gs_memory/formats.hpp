// tests/gs_memory/formats.hpp — the storage formats and layouts the tests sweep.
#pragma once

#include <array>

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

}  // namespace gs::mem::test
