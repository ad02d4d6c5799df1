// Properties over random inputs: the fill rule against the span rule, the quantiser's assignment.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <glm/geometric.hpp>

#include "pipeline/normal_map.hpp"
#include "pipeline/raster.hpp"
#include "span_rule.hpp"

namespace gsdot3::pipeline {
namespace {

RC_GTEST_PROP(FillRule, AnyTriangleMatchesTheSpanRule, ()) {
  const auto c = *rc::gen::container<std::vector<int>>(6, rc::gen::inRange(-32 * 16, 32 * 16));
  const std::array<xy124, 3> v{xy124{c[0], c[1]}, xy124{c[2], c[3]}, xy124{c[4], c[5]}};
  const triangle_setup t = setup_triangle(v);
  RC_PRE(t.area2 != 0);
  for (int y = -33; y <= 33; ++y)
    for (int x = -33; x <= 33; ++x) RC_ASSERT(covers(t, x, y) == test::span_rule_covers(v, x, y));
}

// Two triangles sharing an edge never both cover a pixel, and together cover what the span rule
// gives for their union (here: each pixel is covered by at most one of them).
RC_GTEST_PROP(FillRule, SharedEdgeIsDrawnOnce, ()) {
  const auto c = *rc::gen::container<std::vector<int>>(8, rc::gen::inRange(-24 * 16, 24 * 16));
  const xy124 a{c[0], c[1]}, b{c[2], c[3]}, p{c[4], c[5]}, q{c[6], c[7]};
  const triangle_setup t1 = setup_triangle({a, b, p}), t2 = setup_triangle({b, a, q});
  RC_PRE(t1.area2 != 0 && t2.area2 != 0);
  // p and q on opposite sides of the edge a–b.
  RC_PRE((t1.area2 > 0) == (t2.area2 > 0));
  for (int y = -25; y <= 25; ++y)
    for (int x = -25; x <= 25; ++x) RC_ASSERT(!(covers(t1, x, y) && covers(t2, x, y)));
}

// Every texel is mapped to the palette entry nearest to it (largest dot product; on a tie the first
// such entry), and every entry is a unit vector.
RC_GTEST_PROP(Quantiser, AssignsNearestUnitEntries, ()) {
  const int side = 8;
  std::vector<glm::vec3> normals;
  for (int i = 0; i < side * side; ++i) {
    const auto xy = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-100, 101));
    glm::vec3 n(static_cast<float>(xy[0]), static_cast<float>(xy[1]), std::fabs(static_cast<float>(xy[2])) + 1.0f);
    normals.push_back(glm::normalize(n));
  }
  const int entries = *rc::gen::inRange(1, 40);
  const normal_map m = quantise(normals, side, side, entries);
  RC_ASSERT(m.palette.size() <= static_cast<std::size_t>(entries));
  for (const glm::vec3& p : m.palette) RC_ASSERT(std::fabs(glm::length(p) - 1.0f) < 1e-4f);
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const float got = glm::dot(normals[i], m.palette[m.index[i]]);
    for (std::size_t j = 0; j < m.palette.size(); ++j)
      if (j < m.index[i])
        RC_ASSERT(glm::dot(normals[i], m.palette[j]) < got);
      else
        RC_ASSERT(glm::dot(normals[i], m.palette[j]) <= got);
  }
}

}  // namespace
}  // namespace gsdot3::pipeline
