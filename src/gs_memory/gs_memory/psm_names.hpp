// gs_memory/psm_names.hpp — the manual's names of the storage formats, both ways.
#pragma once

#include <optional>
#include <string_view>

#include "gs_memory/format.hpp"

namespace gs::mem {

struct psm_name_entry {
  psm p;
  std::string_view name;
};
inline constexpr psm_name_entry psm_names[] = {
    {psm::PSMCT32, "PSMCT32"}, {psm::PSMCT24, "PSMCT24"}, {psm::PSMCT16, "PSMCT16"}, {psm::PSMCT16S, "PSMCT16S"},
    {psm::PSMT8, "PSMT8"},     {psm::PSMT8H, "PSMT8H"},   {psm::PSMT4, "PSMT4"},     {psm::PSMT4HL, "PSMT4HL"},
    {psm::PSMT4HH, "PSMT4HH"}, {psm::PSMZ32, "PSMZ32"},   {psm::PSMZ24, "PSMZ24"},   {psm::PSMZ16, "PSMZ16"},
    {psm::PSMZ16S, "PSMZ16S"}};

constexpr std::string_view name_of(psm p) noexcept {
  for (const auto& e : psm_names)
    if (e.p == p) return e.name;
  return "?";
}

constexpr std::optional<psm> parse_psm(std::string_view name) noexcept {
  for (const auto& e : psm_names)
    if (e.name == name) return e.p;
  return std::nullopt;
}

}  // namespace gs::mem
