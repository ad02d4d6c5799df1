// vectors/units.hpp — the GS units `gsdot3 vectors` generates and verifies test vectors for.
//
// Each unit is one row of units(): its name, its input and output fields (hex, fixed width), the
// model function that computes the outputs, and its case generators (level 1 boundary crossing,
// weighted random cases for level 2, and the exhaustive domain where it is finite and practical).
// The line format is documented in docs/vectors.md.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "gs_arith/options.hpp"

namespace gsdot3::vectors {

// One field of a vector line, written as exactly `digits` lower-case hex digits.
struct field {
  std::string_view name;
  int digits;
};

using values = std::vector<std::uint64_t>;

// An input outside the unit's domain (a reserved register value, a selector out of range, ...).
struct domain_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A deterministic generator (splitmix64), so that `--seed N` gives the same cases everywhere.
class random {
 public:
  explicit random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  std::uint64_t below(std::uint64_t n);  // uniform in [0, n), n >= 1
  bool coin() { return (next() & 1) != 0; }
  // A byte: half the time one of the boundary patterns, otherwise uniform.
  std::uint8_t colour_byte();
  std::uint32_t colour_word();  // four colour_byte()s

 private:
  std::uint64_t state_;
};

// The boundary patterns of an 8-bit channel that level 1 crosses with every mode.
inline constexpr std::uint8_t boundary_bytes[] = {0x00, 0x01, 0x7F, 0x80, 0x81, 0xFE, 0xFF};

using case_sink = std::function<void(const values& inputs)>;

struct unit {
  std::string_view name;
  std::string_view summary;
  std::vector<field> inputs;
  std::vector<field> outputs;
  // The model's outputs; throws domain_error for inputs outside the unit's domain.
  values (*evaluate)(const values& inputs, const gs::model_options& o);
  void (*level1)(const case_sink& emit);
  void (*random_case)(random& rng, const case_sink& emit);
  void (*exhaustive)(const case_sink& emit);  // nullptr when the domain is not practical to enumerate
  std::string_view exhaustive_domain;         // what --level all enumerates, or why it is refused
};

const std::vector<unit>& units();
const unit* find_unit(std::string_view name);  // nullptr if unknown
std::string_view unit_names();                 // "blend|tfx|..."

}  // namespace gsdot3::vectors
