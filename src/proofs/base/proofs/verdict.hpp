// proofs/verdict.hpp — what a claim's evaluation returns, and the accumulators a sweep fills.
//
// A verdict is `proven` (the predicate holds on the whole domain), `refuted` (with the number of
// counterexamples and the first few, in domain order), or `bound` (the tight min / max of a
// quantity, with the inputs that reach them). Accumulators keep domain indices, not text, so the hot
// loops stay cheap; merging two accumulators of consecutive index ranges (left then right) keeps the
// earliest witnesses, so the result does not depend on how the domain was split between threads.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace gsdot3::proofs {

enum class verdict { proven, refuted, bound };
const char* name(verdict v) noexcept;

// A named number the claim reports (an integer count or extreme, or a real such as an angle).
struct figure {
  std::string name;
  std::variant<std::int64_t, double> value;
  friend bool operator==(const figure&, const figure&) = default;
};
// An integer as is; a real with up to 9 significant digits.
std::string to_string(const std::variant<std::int64_t, double>& value);

struct outcome {
  verdict result = verdict::proven;
  std::uint64_t domain_size = 0;
  std::uint64_t counterexamples = 0;
  std::vector<figure> figures;
  std::vector<std::string> witnesses;  // "inputs => observed, expected" lines, hex and decimal
  std::string note;                    // one sentence: what the verdict means here
  std::vector<std::string> table;      // optional markdown table lines, printed after the figures
  // The evaluation read neither the model options nor the domain options (e.g. a brute force of
  // option-free statements): every variant would repeat it, so the runner evaluates none.
  bool option_free = false;

  const figure* find(std::string_view figure_name) const noexcept;
  std::int64_t integer(std::string_view figure_name) const;  // throws if absent or not integral
  double real(std::string_view figure_name) const;           // either kind, as a double
};

// How many witnesses a claim reports at most.
inline constexpr std::size_t witness_cap = 4;

// At most `witness_cap` domain indices in a fixed array, so that every accumulator built from
// tally / extremes / integers is trivially copyable (a shard writes its chunks' accumulators as bytes).
struct index_list {
  std::array<std::uint64_t, witness_cap> at{};
  std::size_t n = 0;
  void push_back(std::uint64_t i) noexcept { at[n++] = i; }
  std::size_t size() const noexcept { return n; }
  bool empty() const noexcept { return n == 0; }
  const std::uint64_t* begin() const noexcept { return at.data(); }
  const std::uint64_t* end() const noexcept { return at.data() + n; }
  std::uint64_t operator[](std::size_t k) const noexcept { return at[k]; }
  friend bool operator==(const index_list& a, const index_list& b) noexcept {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator==(const index_list& a, const std::vector<std::uint64_t>& b) noexcept {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
};

// Counterexamples: their number and the first `witness_cap` domain indices.
struct tally {
  std::uint64_t count = 0;
  index_list first;

  void add(std::uint64_t index) {
    ++count;
    if (first.size() < witness_cap) first.push_back(index);
  }
  // `later` covers indices after all of this one's.
  void merge(const tally& later) {
    count += later.count;
    for (auto i : later.first)
      if (first.size() < witness_cap) first.push_back(i);
  }
};

// The least and greatest value seen, each with the first index that reaches it.
struct extremes {
  std::int64_t min = std::numeric_limits<std::int64_t>::max();
  std::int64_t max = std::numeric_limits<std::int64_t>::min();
  std::uint64_t arg_min = 0, arg_max = 0;

  bool empty() const noexcept { return min > max; }
  void add(std::int64_t v, std::uint64_t index) noexcept {
    if (v < min) {
      min = v;
      arg_min = index;
    }
    if (v > max) {
      max = v;
      arg_max = index;
    }
  }
  void merge(const extremes& later) noexcept {
    if (later.min < min) {
      min = later.min;
      arg_min = later.arg_min;
    }
    if (later.max > max) {
      max = later.max;
      arg_max = later.arg_max;
    }
  }
};

// "0x7f (127)": a value in hex and decimal; negative values show their `bits`-wide two's complement.
std::string hexdec(std::int64_t v, int bits = 8);
// A real with `digits` significant digits ("%.*g"; figures are printed with 9).
std::string real_text(double v, int digits = 9);
// A double exactly, as a hexadecimal float ("%a"), so a witness can be pasted back.
std::string hex_float(double v);

}  // namespace gsdot3::proofs
