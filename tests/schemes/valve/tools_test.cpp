// tests/schemes/valve/tools_test.cpp — `gsdot3 ssbump from-normal|from-height` on tiny PNGs whose
// output is worked out by hand, and their one-line errors. argv[1] is the gsdot3 binary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/files.hpp"
#include "pipeline/image_io.hpp"
#include "common/temp_dir.hpp"

namespace {

std::string gsdot3_bin;
namespace fs = std::filesystem;

struct run_result {
  int code;
  std::string err;
};

fs::path dir();

run_result run(const std::string& args) {
  const fs::path err = dir() / "stderr.txt";
  const int status = std::system((gsdot3_bin + " " + args + " 2>" + err.string() + " >/dev/null").c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WEXITSTATUS(status), text};
}

fs::path dir() {
  static const fs::path d = [] { return gsdot3::test::fresh_temp_dir("gsdot3-ssbump-tools"); }();
  return d;
}

// Three texels by hand (N = 2c/255 − 1, B from common_fxc.h):
//  (128, 128, 255): 255·D = (85.94, 85.34, 83.71) → truncated (85, 85, 83).
//  (232, 128, 201): N ≈ (0.8196, 0.0039, 0.5765); N·B0 = 1.0020 → saturate 1; N·B1 = 0.0010 → d1 ≈ 1e-6;
//                   N·B2 = −0.0045 → 0; so 255·D ≈ (254.9997, 0.0003, 0) → (254, 0, 0), rounded (255, 0, 0).
//  (128, 128, 0):   every N·B_i < 0, Σd = 0 → NaN weights → written as 0.
TEST(SsbumpTool, FromNormalByHand) {
  gsdot3::pipeline::image in{3, 1, 3, {128, 128, 255, 232, 128, 201, 128, 128, 0}};
  gsdot3::pipeline::write_png(dir() / "n.png", in);
  ASSERT_EQ(run("ssbump from-normal " + (dir() / "n.png").string() + " " + (dir() / "o.png").string()).code, 0);
  auto out = gsdot3::pipeline::read_png_rgba(dir() / "o.png");
  ASSERT_EQ(out.width, 3);
  const std::vector<std::uint8_t> want = {85, 85, 83, 255, 254, 0, 0, 255, 0, 0, 0, 255};
  EXPECT_EQ(out.rgba, want);
  ASSERT_EQ(
      run("ssbump from-normal --rounding nearest " + (dir() / "n.png").string() + " " + (dir() / "o2.png").string())
          .code,
      0);
  out = gsdot3::pipeline::read_png_rgba(dir() / "o2.png");
  const std::vector<std::uint8_t> nearest = {86, 85, 84, 255, 255, 0, 0, 255, 0, 0, 0, 255};
  EXPECT_EQ(out.rgba, nearest);
}

// A flat height field: every channel 1/√3 = 0.57735 → trunc(147.22) = 147. With an alpha channel
// the height comes from alpha, as in Source (the RGB noise is ignored).
TEST(SsbumpTool, FromHeightFlatIs147) {
  gsdot3::pipeline::image grey{8, 8, 1, std::vector<std::uint8_t>(64, 128)};
  gsdot3::pipeline::write_png(dir() / "h.png", grey);
  const auto r =
      run("ssbump from-height --scale 4 --threads 2 " + (dir() / "h.png").string() + " " + (dir() / "hs.png").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("100%"), std::string::npos);  // progress on stderr
  const auto out = gsdot3::pipeline::read_png_rgba(dir() / "hs.png");
  for (std::size_t i = 0; i < 64; ++i) {
    EXPECT_EQ(out.rgba[4 * i], 147);
    EXPECT_EQ(out.rgba[4 * i + 1], 147);
    EXPECT_EQ(out.rgba[4 * i + 2], 147);
  }
}

TEST(SsbumpTool, HelpAndOneLineErrors) {
  EXPECT_EQ(run("ssbump from-height --help").code, 0);
  std::ofstream(dir() / "bad.png") << "not a png";
  for (const std::string& args :
       std::vector<std::string>{"ssbump from-normal " + (dir() / "bad.png").string() + " x.png",
                                "ssbump from-normal " + (dir() / "missing.png").string() + " x.png",
                                "ssbump from-height " + (dir() / "h.png").string() + " x.png --scale 0",
                                "ssbump from-height " + (dir() / "h.png").string() + " x.png --scale 1 --height alpha",
                                "ssbump from-normal " + (dir() / "n.png").string() + " x.png --rounding up"}) {
    const auto r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err.rfind("gsdot3: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  if (argc < 2) return 2;
  gsdot3_bin = argv[1];
  return RUN_ALL_TESTS();
}
