// tests of src/vectors (`gsdot3 vectors gen|ver`): hand-written lines whose expected outputs come from
// the hardware recordings and the formulas of ../shared/spec/gs-alu-facts.md, gen -> ver round trips, and the
// reporting of corrupted and malformed lines.
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vectors/format.hpp"
#include "vectors/generate.hpp"
#include "vectors/units.hpp"
#include "vectors/verify.hpp"

namespace v = gsdot3::vectors;

namespace {

std::string gen(std::string_view unit, v::level lvl, std::uint64_t seed = 1, std::size_t count = 500) {
  v::generate_settings s;
  s.lvl = lvl;
  s.seed = seed;
  s.random_cases = count;
  std::ostringstream out;
  v::generate(*v::find_unit(unit), s, out);
  return out.str();
}

struct ver_run {
  v::verify_result result;
  std::string report;
};
ver_run ver(const std::string& text, v::verify_settings s = {}) {
  std::istringstream in(text);
  std::ostringstream report;
  const auto r = v::verify_vectors(in, report, s);
  return {r, report.str()};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}
std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}
std::string header(std::string_view unit) { return v::header_line(*v::find_unit(unit), gs::model_options{}) + "\n"; }

// Replaces the last field of a case line with `value`.
std::string with_last_field(const std::string& line, const std::string& value) {
  return line.substr(0, line.rfind(' ') + 1) + value;
}

}  // namespace

// Expected outputs from outside the model: the HW example of ../shared/spec/gs-alu-facts.md ("Alpha blend"),
// the simpletexture recording, and COLCLAMP's clamp/wrap definition.
TEST(Vectors, HandWrittenLinesFromTheRecordingsAndTheDigest) {
  const std::string text = header("blend") +
                           "# (Cs - Cd) * As + Cd, src ff402040, dst ff204020 -> ff5f005f on a PS2"
                           " (../shared/spec/gs-alu-facts.md, \"Alpha blend\")\n"
                           "0000000000000044 ff402040 ff204020 => 05f 000 05f\n";
  const auto blend = ver(text);
  EXPECT_EQ(blend.result.passed, 1u);
  EXPECT_EQ(blend.result.failed, 0u) << blend.report;
  // ps2autotests simpletexture: texel ff808080, MODULATE, TCC = RGB, vertex 80808080 -> 80808080.
  const auto tfx = ver(header("tfx") + "0 0 ff808080 4000 4000 4000 4000 => 80808080\n");
  EXPECT_EQ(tfx.result.failed, 0u) << tfx.report;
  // CLAMP = 1 clamps to 0..255, CLAMP = 0 keeps the low 8 bits: -1, 256, 127.
  const auto clamp = ver(header("colclamp") + "1 7ff 100 07f => 00 ff 7f\n0 7ff 100 07f => ff 00 7f\n");
  EXPECT_EQ(clamp.result.passed, 2u);
  EXPECT_EQ(clamp.result.failed, 0u) << clamp.report;
  EXPECT_EQ(clamp.report, "2 passed, 0 failed\n");
  // stq: 1.0 / 1.0 on a 16-texel texture is 16 texels = 0x100 sixteenths; 1.5 / 0.5 with TW = 0 is 3 texels
  // (0x30); -2^-8 / 1 (3b800000 negated) truncates to 0 under the default, floors to -1 under
  // floor_1_64; 3000 saturates at 2047 texels (0x7ff0) unless stq_range = x86_int32 (0xbb80).
  const auto stq = ver(header("stq") + "3f800000 3f800000 4 => 00000100\n3fc00000 3f000000 0 => 00000030\n" +
                       "bb800000 3f800000 0 => 00000000\n453b8000 3f800000 0 => 00007ff0\n");
  EXPECT_EQ(stq.result.failed, 0u) << stq.report;
  EXPECT_EQ(stq.result.passed, 4u);
  gs::model_options other;
  other.stq_convert = gs::stq_convert_mode::floor_1_64;
  other.stq_range = gs::stq_range_mode::x86_int32;
  const auto stq_other = ver(v::header_line(*v::find_unit("stq"), other) + "\nbb800000 3f800000 0 => ffffffff\n" +
                             "453b8000 3f800000 0 => 0000bb80\n");
  EXPECT_EQ(stq_other.result.failed, 0u) << stq_other.report;
  EXPECT_EQ(stq_other.result.passed, 2u);
}

TEST(Vectors, EveryUnitRoundTripsAtLevels1And2) {
  for (const auto& u : v::units()) {
    for (auto lvl : {v::level::one, v::level::two}) {
      const std::string text = gen(u.name, lvl);
      const auto run = ver(text);
      const std::size_t cases = lines_of(text).size() - 2;  // header and field comment
      EXPECT_GT(cases, 0u) << u.name;
      EXPECT_EQ(run.result.passed, cases) << u.name;
      EXPECT_EQ(run.result.failed, 0u) << u.name << "\n" << run.report;
      EXPECT_EQ(run.report, std::to_string(cases) + " passed, 0 failed\n");
    }
  }
}

TEST(Vectors, ExhaustiveLevelWhereItIsPractical) {
  const std::string text = gen("colclamp", v::level::all);
  EXPECT_EQ(lines_of(text).size(), 2u + 2u * 2048u);  // CLAMP x every 11-bit value
  EXPECT_EQ(ver(text).result.failed, 0u);
  EXPECT_THROW(gen("blend", v::level::all), v::domain_error);
}

TEST(Vectors, Level2IsDeterministicPerSeed) {
  EXPECT_EQ(gen("pixel", v::level::two, 7, 50), gen("pixel", v::level::two, 7, 50));
  EXPECT_NE(gen("pixel", v::level::two, 7, 50), gen("pixel", v::level::two, 8, 50));
}

TEST(Vectors, CorruptedLineIsReportedAsInputsObservedExpected) {
  auto lines = lines_of(gen("blend", v::level::one));
  const std::string original = lines[10];
  const std::string expected = original.substr(original.rfind(' ') + 1);
  const std::string wrong = expected == "000" ? "001" : "000";
  lines[10] = with_last_field(original, wrong);
  const auto run = ver(join(lines));
  EXPECT_EQ(run.result.failed, 1u);
  EXPECT_EQ(run.result.passed, lines.size() - 3);
  // "inputs => observed expected: value", then the closing line.
  const std::string mismatch =
      with_last_field(original, wrong) + " expected: " + original.substr(original.find("=> ") + 3);
  EXPECT_EQ(run.report, mismatch + "\n" + std::to_string(lines.size() - 3) + " passed, 1 failed\n");
}

TEST(Vectors, MalformedLinesNameTheirLineNumberAndTheRunContinues) {
  auto lines = lines_of(gen("colclamp", v::level::one));
  lines.insert(lines.begin() + 4, "1 zz 000 000 => 00 00 00");   // line 5: not hex
  lines.insert(lines.begin() + 6, "1 000 000 => 00 00 00");      // line 7: too few inputs
  lines.insert(lines.begin() + 8, "2 000 000 000 => 00 00 00");  // line 9: CLAMP = 2 is outside the domain
  lines.insert(lines.begin() + 10, "1 000 000 000 00 00 00");    // line 11: no =>
  const auto run = ver(join(lines));
  EXPECT_EQ(run.result.failed, 4u);
  EXPECT_EQ(run.result.passed, lines.size() - 2 - 4);
  for (int n : {5, 7, 9, 11})
    EXPECT_NE(run.report.find("line " + std::to_string(n) + ": malformed: "), std::string::npos) << n << "\n"
                                                                                                 << run.report;
}

TEST(Vectors, ErrorCapAndErrorStop) {
  auto lines = lines_of(gen("colclamp", v::level::one));
  for (std::size_t i = 2; i < 12; ++i)
    lines[i] = with_last_field(lines[i], lines[i].substr(lines[i].size() - 2) == "00" ? "01" : "00");
  v::verify_settings capped;
  capped.max_errors = 3;
  const auto run = ver(join(lines), capped);
  EXPECT_EQ(run.result.failed, 10u);
  const auto report = lines_of(run.report);
  ASSERT_EQ(report.size(), 3u + 1u + 1u);  // 3 shown, the cap notice, the closing line
  EXPECT_EQ(report[3], "... further failures not shown (--errors 3)");
  EXPECT_EQ(report[4], std::to_string(lines.size() - 12) + " passed, 10 failed");

  v::verify_settings stop;
  stop.errorstop = true;
  const auto stopped = ver(join(lines), stop);
  EXPECT_EQ(stopped.result.failed, 1u);
  EXPECT_EQ(stopped.result.passed, 0u);
}

TEST(Vectors, HeaderErrors) {
  EXPECT_THROW(ver("0 000 000 000 => 00 00 00\n"), v::format_error);                      // no header
  EXPECT_THROW(ver("gsdot3-vectors 2 unit=colclamp\n"), v::format_error);                 // another version
  EXPECT_THROW(ver("gsdot3-vectors 1 unit=fog\n"), v::format_error);                      // unknown unit
  EXPECT_THROW(ver("gsdot3-vectors 1 unit=blend blend_shift=round\n"), v::format_error);  // bad option
  EXPECT_THROW(ver(""), v::format_error);                                                 // empty input
}

// The header's options are the model's: a blend_shift=truncate file disagrees with floor.
TEST(Vectors, HeaderOptionsSelectTheModel) {
  // (0x20 - 0x40) * 0xff = -8160: floor(-63.75) = -64, truncate -63; + 0x40 -> 0 or 1.
  const std::string line = "0000000000000044 ff402040 ff204020 => 05f 001 05f\n";
  EXPECT_EQ(ver("gsdot3-vectors 1 unit=blend blend_shift=truncate\n" + line).result.failed, 0u);
  EXPECT_EQ(ver(header("blend") + line).result.failed, 1u);
}

TEST(Vectors, Ps2autotestsBlendRecordings) {
  const std::filesystem::path file = std::filesystem::path(GSDOT3_HW_DIR) / "ps2autotests-gs-blend.expected";
  if (!std::filesystem::exists(file))
    GTEST_SKIP() << "hardware recordings not found: " << file << " (../shared/hw missing)";
  std::ifstream in(file);
  std::ostringstream report;
  const auto r = v::verify_ps2autotests(in, report, {});
  EXPECT_EQ(report.str(), "486 passed, 0 failed\n");
  EXPECT_EQ(r.failed, 0u);
  // Under the refuted truncating shift the recordings disagree (24 mismatches, ../shared/spec/gs-alu-facts.md).
  std::ifstream again(file);
  std::ostringstream what_if;
  v::verify_settings s;
  s.max_errors = 0;
  s.option_overrides = {{"blend_shift", "truncate"}};
  EXPECT_EQ(v::verify_ps2autotests(again, what_if, s).failed, 24u);
}

TEST(Vectors, Ps2autotestsMalformedLine) {
  std::istringstream in(
      "-- TEST BEGIN\n  src: ffff00ff, dst: ff00ff00, fix: ff => ffff00ff\n0000: (Cs - Cs) * As + Cs\n  src: zz\n");
  std::ostringstream report;
  const auto r = v::verify_ps2autotests(in, report, {});
  EXPECT_EQ(r.failed, 2u);
  EXPECT_NE(report.str().find("line 2: malformed: a sample before any"), std::string::npos) << report.str();
  EXPECT_NE(report.str().find("line 4: malformed: "), std::string::npos) << report.str();
}
