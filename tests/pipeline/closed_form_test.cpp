// Closed-form scenes: a flat quad, a constant normal, a directional light. Every covered pixel's
// DPB byte must equal the method's value computed here by plain integer arithmetic from the
// paper's equations (not through gs_arith or the renderer); uncovered pixels keep the clear value's
// sum 0x80 + 0x80 + 0x80 = 0x80 (mod 256).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "pipeline/encoders.hpp"
#include "pipeline/render.hpp"
#include "test_scenes.hpp"

namespace gsdot3::pipeline {
namespace {

int byte_of(std::uint32_t word, int c) { return static_cast<int>((word >> (8 * c)) & 0xFF); }

// Section 3.6: a = nearest(127·L) (the sphere map stores 128 − a), b = nearest(127·n); the three
// passes give (a·b >> 7) + 128 per channel, "identical with an ordinary char multiplication a·b with
// a signed shift right by 7 (offset by 128)"; R+G+B mod 256.
int four_pass_expected(glm::vec3 n, glm::vec3 T) {
  const st c = sphere_coordinates(T);
  const int u = std::min(static_cast<int>(std::lround(c.s * 1024)) >> 4, 63),
            v = std::min(static_cast<int>(std::lround(c.t * 1024)) >> 4, 63);
  const std::uint32_t sph = sphere_map(64, 64)[static_cast<std::size_t>(v * 64 + u)];
  int sum = 0;
  for (int k = 0; k < 3; ++k) {
    const int a = 128 - byte_of(sph, k), b = nearest(n[k] * 127);
    sum += ((a * b) >> 7) + 128;
  }
  return sum & 0xFF;
}

// Section 3.5: L = 128 + (char)(s·T); pass 1 writes P·L >> 7, pass 2 subtracts N·L >> 7, the post
// filter adds n'_a to each channel; R+G+B mod 256.
int two_pass_expected(glm::vec3 n, glm::vec3 T, int s) {
  const two_pass_texel t = pack_two_pass(n);
  const int na = t.negative.a.value();
  const int P[3] = {t.positive.r.value(), t.positive.g.value(), t.positive.b.value()};
  const int N[3] = {t.negative.r.value(), t.negative.g.value(), t.negative.b.value()};
  int sum = 0;
  for (int k = 0; k < 3; ++k) {
    const int L = 128 + static_cast<signed char>(static_cast<int>(static_cast<float>(s) * T[k]));
    sum += ((P[k] * L) >> 7) - ((N[k] * L) >> 7) + na;
  }
  return sum & 0xFF;
}

// Section 3.5's three-pass alternative: passes 1 and 2 as above, then 128 + N − P added to each
// channel instead of n'_a; R+G+B mod 256.
int three_pass_expected(glm::vec3 n, glm::vec3 T, int s) {
  const two_pass_texel t = pack_two_pass(n);
  const int P[3] = {t.positive.r.value(), t.positive.g.value(), t.positive.b.value()};
  const int N[3] = {t.negative.r.value(), t.negative.g.value(), t.negative.b.value()};
  int sum = 0;
  for (int k = 0; k < 3; ++k) {
    const int L = 128 + static_cast<signed char>(static_cast<int>(static_cast<float>(s) * T[k]));
    sum += ((P[k] * L) >> 7) - ((N[k] * L) >> 7) + 128 + N[k] - P[k];
  }
  return sum & 0xFF;
}

// Section 2: 128 + NMpos·TLpos + NMneg·TLneg − NMneg·TLpos − NMpos·TLneg per channel (each >> 7).
int baseline_expected(glm::vec3 n, glm::vec3 T) {
  int sum = 0;
  for (int k = 0; k < 3; ++k) {
    const int np = nearest(std::max(n[k], 0.0f) * 127), nn = nearest(std::max(-n[k], 0.0f) * 127);
    const int tp = nearest(std::max(T[k], 0.0f) * 127), tn = nearest(std::max(-T[k], 0.0f) * 127);
    sum += 128 + ((np * tp) >> 7) + ((nn * tn) >> 7) - ((nn * tp) >> 7) - ((np * tn) >> 7);
  }
  return sum & 0xFF;
}

void check(method m, glm::vec3 n, glm::vec3 T, int expected) {
  test::flat_quad q = test::make_flat_quad(n, T);
  for (raster_path path : {raster_path::cached, raster_path::reference}) {
    render_options o;
    o.path = path;
    const frame f = render(q.s, q.ps, m, o);
    for (int y = 0; y < q.s.height; ++y)
      for (int x = 0; x < q.s.width; ++x) {
        const bool inside = x >= 8 && x < 56 && y >= 8 && y < 40;
        const int got = f.dot[0][static_cast<std::size_t>(y * q.s.width + x)];
        ASSERT_EQ(got, inside ? expected : 0x80)
            << name(m) << " pixel " << x << "," << y << " n=(" << n.x << "," << n.y << "," << n.z << ") T=(" << T.x
            << "," << T.y << "," << T.z << ") got 0x" << std::hex << got << " expected 0x"
            << (inside ? expected : 0x80);
      }
  }
}

std::vector<std::pair<glm::vec3, glm::vec3>> cases() {
  std::vector<std::pair<glm::vec3, glm::vec3>> c = {{{0, 0, 1}, {0, 0, 1}},
                                                    {{0, 0, 1}, {1, 0, 0.2f}},
                                                    {{0.5f, -0.3f, 0.8f}, {-0.4f, 0.6f, 0.7f}},
                                                    {{-0.7f, 0.1f, 0.7f}, {0.7f, -0.1f, 0.7f}},
                                                    {{0.2f, 0.9f, 0.3f}, {0.3f, 0.5f, 0.8f}}};
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  while (c.size() < 40) {
    glm::vec3 n{g(rng), g(rng), std::fabs(g(rng)) + 0.05f}, T{g(rng), g(rng), std::fabs(g(rng)) + 0.3f};
    c.push_back({glm::normalize(n), glm::normalize(T)});
  }
  return c;
}

TEST(ClosedForm, FourPass) {
  for (auto [n, T] : cases())
    check(method::four_pass, glm::normalize(n), glm::normalize(T),
          four_pass_expected(glm::normalize(n), glm::normalize(T)));
}

TEST(ClosedForm, TwoPass) {
  for (auto [n, T] : cases())
    check(method::two_pass, glm::normalize(n), glm::normalize(T),
          two_pass_expected(glm::normalize(n), glm::normalize(T), 122));
}

TEST(ClosedForm, ThreePass) {
  for (auto [n, T] : cases())
    check(method::three_pass, glm::normalize(n), glm::normalize(T),
          three_pass_expected(glm::normalize(n), glm::normalize(T), 122));
}

// Section 4's Gouraud shading: the quad's vertex normal is the tangent-space (0, 0, 1), so every vertex
// sends 128 + nearest(127·max(T_z, 0)) and the flat quad is that byte (green and blue 0).
TEST(ClosedForm, Gouraud) {
  for (auto [n, T] : cases()) {
    const glm::vec3 t = glm::normalize(T);
    check(method::gouraud, glm::normalize(n), t, 128 + static_cast<int>(std::lround(std::max(t.z, 0.0f) * 127)));
  }
  check(method::gouraud, {0.6f, 0, 0.8f}, {0, 0, -1}, 128);  // facing away: 0, whatever the normal map
}

TEST(ClosedForm, Baseline) {
  for (auto [n, T] : cases())
    check(method::baseline, glm::normalize(n), glm::normalize(T),
          baseline_expected(glm::normalize(n), glm::normalize(T)));
}

// The head-on case in numbers: n = T = (0, 0, 1) is a dot product of 1.0 (128). Four-pass: 127·127 >> 7
// = 126; two-pass: 128·250 >> 7 = 250 for z, and 3·n'_a = 3·85 = 255 instead of n_a = 256, so
// 250 + 255 − 384 = 121 (s/128 of full scale, less one for the rounding of n'_a); three-pass adds
// n_a itself (128 + 128 + 0): 250 + 256 − 384 = 122; baseline 126.
TEST(ClosedForm, HeadOnValues) {
  EXPECT_EQ(dot_value(static_cast<std::uint8_t>(four_pass_expected({0, 0, 1}, {0, 0, 1}))), 126);
  EXPECT_EQ(dot_value(static_cast<std::uint8_t>(two_pass_expected({0, 0, 1}, {0, 0, 1}, 122))), 121);
  EXPECT_EQ(dot_value(static_cast<std::uint8_t>(three_pass_expected({0, 0, 1}, {0, 0, 1}, 122))), 122);
  EXPECT_EQ(dot_value(static_cast<std::uint8_t>(baseline_expected({0, 0, 1}, {0, 0, 1}))), 126);
  check(method::three_pass, {0, 0, 1}, {0, 0, 1}, 122 + 128);
  check(method::four_pass, {0, 0, 1}, {0, 0, 1}, 126 + 128);
}

}  // namespace
}  // namespace gsdot3::pipeline
