#include "proofs/shard.hpp"

#include <charconv>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace gsdot3::proofs {

std::optional<shard_id> parse_shard(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  shard_id s;
  const auto a = std::from_chars(text.data(), text.data() + slash, s.k);
  const auto b = std::from_chars(text.data() + slash + 1, text.data() + text.size(), s.n);
  if (a.ec != std::errc{} || a.ptr != text.data() + slash || b.ec != std::errc{} ||
      b.ptr != text.data() + text.size() || s.n == 0 || s.k >= s.n)
    return std::nullopt;
  return s;
}

namespace {
constexpr char hex_digits[] = "0123456789abcdef";
std::string to_hex(const std::string& bytes) {
  std::string out;
  out.reserve(2 * bytes.size());
  for (unsigned char ch : bytes) out += hex_digits[ch >> 4], out += hex_digits[ch & 15];
  return out;
}
std::string from_hex(const std::string& hex) {
  if (hex.size() % 2 != 0) throw std::invalid_argument("odd-length hex chunk");
  auto nibble = [](char ch) {
    if (ch >= '0' && ch <= '9') return ch - '0';
    if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    throw std::invalid_argument("bad hex digit in a chunk");
  };
  std::string out(hex.size() / 2, '\0');
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<char>(nibble(hex[2 * i]) * 16 + nibble(hex[2 * i + 1]));
  return out;
}
nlohmann::ordered_json options_json(const gs::model_options& o) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& info : gs::option_catalogue())
    j[std::string(info.name)] = std::string(gs::option_value(o, info.name));
  return j;
}
}  // namespace

std::string run_shard(const claim& c, const gs::model_options& base, const run_config& cfg, shard_id shard) {
  run_config rc = cfg;
  auto log = std::make_shared<shard_log>();
  log->m = shard_log::mode::record;
  log->k = shard.k;
  log->n = shard.n;
  rc.sweep.shard = log;
  (void)run_claim(c, base, rc);
  nlohmann::ordered_json doc;
  doc["partial_ledger"] = 1;
  doc["claim"] = c.id;
  doc["shard"] = {{"k", shard.k}, {"n", shard.n}};
  doc["options"] = options_json(base);
  doc["variants"] = cfg.variants;
  doc["brute_force"] = cfg.sweep.brute_force;
  nlohmann::ordered_json sweeps = nlohmann::ordered_json::array();
  for (const auto& r : log->sweeps) {
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    for (const auto& p : r.parts) parts.push_back({p.chunk, to_hex(p.bytes)});
    sweeps.push_back(
        {{"eval", r.eval}, {"call", r.call}, {"n", r.n}, {"chunks", r.chunks}, {"kind", r.kind}, {"parts", parts}});
  }
  doc["sweeps"] = std::move(sweeps);
  return doc.dump() + "\n";
}

merged merge_shards(const std::vector<std::string>& parts, const run_config& cfg) {
  if (parts.empty()) throw std::invalid_argument("no partial ledgers to merge");
  auto log = std::make_shared<shard_log>();
  log->m = shard_log::mode::replay;
  std::string claim_id, options;
  bool variants = true, brute = false;
  unsigned n = 0;
  std::vector<bool> seen;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(parts[i]);
    } catch (const nlohmann::json::exception& e) {
      throw std::invalid_argument("part " + std::to_string(i + 1) + " is not JSON: " + e.what());
    }
    if (!j.is_object() || j.value("partial_ledger", 0) != 1)
      throw std::invalid_argument("part " + std::to_string(i + 1) +
                                  " is not a partial ledger (gsdot3 prove --shard K/N --json)");
    try {
      const auto id = j.at("claim").get<std::string>();
      const auto opts = j.at("options").dump();
      const auto k = j.at("shard").at("k").get<unsigned>(), nn = j.at("shard").at("n").get<unsigned>();
      const bool var = j.at("variants").get<bool>(), bf = j.at("brute_force").get<bool>();
      if (i == 0) {
        claim_id = id, options = opts, n = nn, variants = var, brute = bf;
        seen.assign(n, false);
      }
      if (id != claim_id || opts != options || var != variants || bf != brute || nn != n)
        throw std::invalid_argument("part " + std::to_string(i + 1) +
                                    " is of another run (claim, options, variants, brute force or N differ)");
      if (k >= n || seen[k])
        throw std::invalid_argument("shard " + std::to_string(k) + "/" + std::to_string(n) + " given twice");
      seen[k] = true;
      for (const auto& s : j.at("sweeps")) {
        sweep_record r{s.at("eval").get<std::uint64_t>(), s.at("call").get<std::uint64_t>(),
                       s.at("n").get<std::uint64_t>(),    s.at("chunks").get<std::uint64_t>(),
                       s.at("kind").get<std::uint64_t>(), {}};
        for (const auto& p : s.at("parts"))
          r.parts.push_back({p.at(0).get<std::uint64_t>(), from_hex(p.at(1).get<std::string>())});
        log->sweeps.push_back(std::move(r));
      }
    } catch (const nlohmann::json::exception& e) {
      throw std::invalid_argument("part " + std::to_string(i + 1) + " is malformed: " + e.what());
    }
  }
  if (const std::string gone = missing_shards(seen); !gone.empty())
    throw std::invalid_argument(gone.find_first_of(",-") == std::string::npos
                                    ? "shard " + gone + "/" + std::to_string(n) + " is missing"
                                    : "shards " + gone + " of " + std::to_string(n) +
                                          " are missing (as Slurm's --array=" + gone + " names them)");
  const claim* c = find_claim(claim_id);
  if (c == nullptr) throw std::invalid_argument("unknown claim id '" + claim_id + "' in the parts");
  gs::model_options o;
  const auto option_values = nlohmann::json::parse(options);
  for (const auto& item : option_values.items())
    if (auto err = gs::set_option(o, item.key(), item.value().get<std::string>())) throw std::invalid_argument(*err);
  run_config rc = cfg;
  rc.variants = variants;
  rc.sweep.brute_force = brute;
  rc.sweep.shard = log;
  merged m{run_claim(*c, o, rc), 0};
  m.recomputed_chunks = log->recomputed;
  return m;
}

std::string missing_shards(const std::vector<bool>& seen) {
  std::string out;
  for (std::size_t k = 0; k < seen.size(); ++k) {
    if (seen[k]) continue;
    std::size_t last = k;
    while (last + 1 < seen.size() && !seen[last + 1]) ++last;
    if (!out.empty()) out += ',';
    out += std::to_string(k);
    if (last > k) out.append(1, '-').append(std::to_string(last));
    k = last;
  }
  return out;
}

}  // namespace gsdot3::proofs
