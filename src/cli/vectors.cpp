// gsdot3 vectors — TestFloat-style test vectors for the GS colour ALU (docs/vectors.md):
//   gsdot3 vectors gen --unit U [--level 1|2|all] [--seed N] [--count N] [--option NAME=VALUE] [-o FILE]
//   gsdot3 vectors ver [FILE|-] [--errors N] [--errorstop] [--format gsdot3|ps2autotests] [--option NAME=VALUE]
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "model_args.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/profiles.hpp"
#include "probe/recording.hpp"
#include "vectors/format.hpp"
#include "vectors/generate.hpp"
#include "vectors/units.hpp"
#include "vectors/verify.hpp"

namespace gsdot3::cli {
namespace {

namespace v = gsdot3::vectors;

std::vector<std::pair<std::string, std::string>> parse_options(const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> out;
  gs::model_options check;
  for (const auto& item : items) {
    out.push_back(split_assignment("--option", item));
    if (auto err = gs::set_option(check, out.back().first, out.back().second)) throw usage_error("--option: " + *err);
  }
  return out;
}

// A profile as option assignments (every option), to put before the --option ones.
std::vector<std::pair<std::string, std::string>> profile_options(const std::string& name) {
  std::vector<std::pair<std::string, std::string>> out;
  if (name.empty()) return out;
  gs::model_options check;
  if (auto err = gs::apply_profile(check, name)) throw usage_error("--profile: " + *err);
  for (const auto& row : gs::option_catalogue()) out.emplace_back(row.name, gs::option_value(check, row.name));
  return out;
}

struct gen_args {
  std::string unit, level = "1", output, profile;
  std::uint64_t seed = 1;
  std::size_t count = 10000;
  std::vector<std::string> options;
};

void run_gen(const gen_args& a) {
  const v::unit* u = v::find_unit(a.unit);
  if (!u) throw usage_error("--unit: unknown unit '" + a.unit + "' (one of " + std::string(v::unit_names()) + ")");
  v::generate_settings s;
  s.lvl = a.level == "1" ? v::level::one : a.level == "2" ? v::level::two : v::level::all;
  s.seed = a.seed;
  s.random_cases = a.count;
  for (const auto& [name, value] : profile_options(a.profile)) gs::set_option(s.options, name, value);
  for (const auto& [name, value] : parse_options(a.options)) gs::set_option(s.options, name, value);
  if (s.lvl == v::level::all && !u->exhaustive)
    throw usage_error("--level all: unit " + a.unit + ": " + std::string(u->exhaustive_domain));
  std::size_t n = 0;
  if (a.output.empty()) {
    n = v::generate(*u, s, std::cout);
    std::cout.flush();
  } else {
    // Written to a temporary file and renamed, so no partial file is left behind.
    const std::string tmp = a.output + ".tmp";
    {
      std::ofstream out(tmp, std::ios::binary);
      if (!out) throw usage_error("-o: cannot write '" + a.output + "'");
      n = v::generate(*u, s, out);
      out.close();
      if (!out) {
        std::filesystem::remove(tmp);
        throw usage_error("-o: error writing '" + a.output + "'");
      }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, a.output, ec);
    if (ec) {
      const std::string why = ec.message();
      std::filesystem::remove(tmp, ec);
      throw usage_error("-o: cannot write '" + a.output + "' (" + why + ")");
    }
  }
  std::cerr << "gsdot3 vectors gen: " << n << " cases for unit " << a.unit << "\n";
}

struct ver_args {
  std::string file = "-", format = "gsdot3", profile;
  std::size_t errors = 20;
  bool errorstop = false;
  std::vector<std::string> options;
};

int run_ver(const ver_args& a) {
  v::verify_settings s;
  s.max_errors = a.errors;
  s.errorstop = a.errorstop;
  s.option_overrides = profile_options(a.profile);
  for (auto& kv : parse_options(a.options)) s.option_overrides.push_back(std::move(kv));
  std::unique_ptr<std::ifstream> file;
  std::istream* in = &std::cin;
  if (a.file != "-") {
    file = std::make_unique<std::ifstream>(a.file);
    if (!*file) throw usage_error("cannot read '" + a.file + "'");
    in = file.get();
  }
  try {
    // A gsdot3 vector file, or (same --format) a `gsdot3 probe decode` recording, told apart by its header.
    const std::string text{std::istreambuf_iterator<char>(*in), std::istreambuf_iterator<char>()};
    std::istringstream body(text);
    const v::verify_result r = a.format == "ps2autotests"  ? v::verify_ps2autotests(body, std::cout, s)
                               : probe::is_recording(text) ? probe::verify_recording(body, std::cout, s)
                                                           : v::verify_vectors(body, std::cout, s);
    return r.failed > 0 ? 1 : 0;
  } catch (const v::format_error& e) {
    throw usage_error((a.file == "-" ? std::string("<stdin>") : a.file) + ": " + e.what());
  }
}

std::string units_help() {
  std::string s = "\nUnits (inputs => outputs, hex fields):";
  for (const auto& u : v::units()) {
    s += "\n  " + std::string(u.name) + ": " + std::string(u.summary) + "\n    ";
    s += v::fields_comment(u).substr(2);
  }
  return s;
}

}  // namespace

void add_vectors_command(CLI::App& app, context& ctx) {
  auto* cmd = app.add_subcommand("vectors",
                                 "TestFloat-style test vectors: generate (gen) and verify (ver), see docs/vectors.md");
  cmd->require_subcommand(1);

  auto gen = std::make_shared<gen_args>();
  auto* g = cmd->add_subcommand(
      "gen", "Write test cases with the model's expected outputs (one per line) to stdout or -o FILE." + units_help());
  g->add_option("--unit", gen->unit, "Unit: " + std::string(v::unit_names()))->required();
  g->add_option("--level", gen->level,
                "1: boundary patterns x every mode; 2: level 1 + weighted random cases; all: exhaustive")
      ->check(CLI::IsMember({"1", "2", "all"}))
      ->capture_default_str();
  g->add_option("--seed", gen->seed, "Seed of the level-2 random cases")->capture_default_str();
  g->add_option("--count", gen->count, "Random cases added by level 2")->capture_default_str();
  g->add_option("--option", gen->options, "Model option NAME=VALUE (recorded in the header). Repeatable.");
  g->add_option("-o,--output", gen->output, "Write to FILE (atomically) instead of stdout");
  g->add_option("--profile", gen->profile, "Emulator option set (" + gs::profile_names() + "); --option overrides it");
  g->callback([gen] { run_gen(*gen); });

  auto ver = std::make_shared<ver_args>();
  auto* r =
      cmd->add_subcommand("ver",
                          "Check each line's observed outputs against the model. Prints each mismatch as\n"
                          "'inputs => observed expected: value', malformed lines as 'line N: malformed: why', and\n"
                          "the closing line 'N passed, M failed'. Exit 1 when anything failed, 2 on a bad header.");
  r->add_option("file", ver->file, "Vector file, or - for stdin")->capture_default_str();
  r->add_option("--errors", ver->errors, "Failures printed in full (0 = all); all are counted")->capture_default_str();
  r->add_flag("--errorstop", ver->errorstop, "Stop at the first failure (mismatch or malformed line)");
  r->add_option("--format", ver->format,
                "gsdot3 (vector files and gsdot3 probe decode recordings, told apart by the header) | ps2autotests "
                "(gs/blend.expected recordings)")
      ->check(CLI::IsMember({"gsdot3", "ps2autotests"}))
      ->capture_default_str();
  r->add_option("--option", ver->options, "Model option NAME=VALUE, over the file's header. Repeatable.");
  r->add_option("--profile", ver->profile,
                "Emulator option set (" + gs::profile_names() + ") over the file's header; --option overrides it");
  r->callback([ver, &ctx] { ctx.exit_code = run_ver(*ver); });
}

}  // namespace gsdot3::cli
