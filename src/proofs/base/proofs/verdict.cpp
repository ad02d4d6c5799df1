#include "proofs/verdict.hpp"

#include <cstdio>
#include <stdexcept>

namespace gsdot3::proofs {

const char* name(verdict v) noexcept {
  switch (v) {
    case verdict::proven: return "proven";
    case verdict::refuted: return "refuted";
    case verdict::bound: return "bound";
  }
  return "?";
}

std::string to_string(const std::variant<std::int64_t, double>& value) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  return real_text(std::get<double>(value));
}

const figure* outcome::find(std::string_view figure_name) const noexcept {
  for (const auto& f : figures)
    if (f.name == figure_name) return &f;
  return nullptr;
}

std::int64_t outcome::integer(std::string_view figure_name) const {
  const figure* f = find(figure_name);
  if (f == nullptr || !std::holds_alternative<std::int64_t>(f->value))
    throw std::out_of_range("no integer figure " + std::string(figure_name));
  return std::get<std::int64_t>(f->value);
}

double outcome::real(std::string_view figure_name) const {
  const figure* f = find(figure_name);
  if (f == nullptr) throw std::out_of_range("no figure " + std::string(figure_name));
  if (const auto* i = std::get_if<std::int64_t>(&f->value)) return static_cast<double>(*i);
  return std::get<double>(f->value);
}

std::string hexdec(std::int64_t v, int bits) {
  const std::uint64_t mask = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1U;
  char buf[64];
  std::snprintf(buf, sizeof buf, "0x%0*llx (%lld)", (bits + 3) / 4,
                static_cast<unsigned long long>(static_cast<std::uint64_t>(v) & mask), static_cast<long long>(v));
  return buf;
}

std::string real_text(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string hex_float(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

}  // namespace gsdot3::proofs

#include "proofs/claim_util.hpp"

namespace gsdot3::proofs {
std::string operands::describe() const { return "a = " + hexdec(a) + ", b = " + hexdec(b); }
}  // namespace gsdot3::proofs
