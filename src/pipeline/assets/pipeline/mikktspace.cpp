// pipeline/mikktspace.cpp — MikkTSpace tangents (see mikktspace.hpp for the rules and where in the
// reference's mikktspace.c each comes from).
#include "pipeline/mikktspace.hpp"
#include "pipeline/word_hash.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace gsdot3::pipeline {

namespace {

using vertex_key = std::array<std::uint32_t, 8>;

// Equal as floats (the reference compares with ==): −0 and +0 are one value.
std::uint32_t word(float f) { return std::bit_cast<std::uint32_t>(f == 0.0f ? 0.0f : f); }

vertex_key key_of(const tangent_corner& c) {
  return {word(c.position.x), word(c.position.y), word(c.position.z), word(c.normal.x),
          word(c.normal.y),   word(c.normal.z),   word(c.uv.x),       word(c.uv.y)};
}

// The reference's NotZero: larger in magnitude than the smallest normal float.
bool not_zero(float f) { return std::fabs(f) > FLT_MIN; }
bool not_zero(glm::vec3 v) { return not_zero(v.x) || not_zero(v.y) || not_zero(v.z); }
glm::vec3 normalised_or_zero(glm::vec3 v) { return not_zero(v) ? v / glm::length(v) : v; }
glm::vec3 in_plane(glm::vec3 v, glm::vec3 n) { return normalised_or_zero(v - n * glm::dot(n, v)); }

glm::vec3 fallback_tangent(glm::vec3 n) {
  const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(axis - n * glm::dot(n, axis));
}

struct triangle_info {
  glm::vec3 os{0.0f}, ot{0.0f};              // unit dP/du and dP/dv (negated when the UV area is negative), or zero
  bool positive = false;                     // UV orientation (assigned by the first group for a "group with any")
  bool group_with_any = true;                // zero UV area: no direction of its own
  bool degenerate = false;                   // two equal positions
  std::array<int, 3> neighbour{-1, -1, -1};  // across edge k (corner k to corner k + 1)
};

// Step 3: neighbours across shared edges (BuildNeighborsFast's pairing order).
void find_neighbours(const std::vector<std::uint32_t>& vertex_of, std::vector<triangle_info>& tri) {
  struct edge {
    std::uint32_t lo, hi;
    std::size_t t;
    int k;
  };
  std::vector<edge> edges;
  for (std::size_t t = 0; t < tri.size(); ++t) {
    if (tri[t].degenerate) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = vertex_of[3 * t + static_cast<std::size_t>(k)];
      const std::uint32_t b = vertex_of[3 * t + static_cast<std::size_t>((k + 1) % 3)];
      edges.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const edge& x, const edge& y) { return std::tie(x.lo, x.hi, x.t) < std::tie(y.lo, y.hi, y.t); });
  auto start = [&](const edge& e) { return vertex_of[3 * e.t + static_cast<std::size_t>(e.k)]; };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const edge& a = edges[i];
    if (tri[a.t].neighbour[static_cast<std::size_t>(a.k)] >= 0) continue;
    for (std::size_t j = i + 1; j < edges.size() && edges[j].lo == a.lo && edges[j].hi == a.hi; ++j) {
      const edge& b = edges[j];
      if (start(b) == start(a) || tri[b.t].neighbour[static_cast<std::size_t>(b.k)] >= 0)
        continue;  // same direction, or taken
      tri[a.t].neighbour[static_cast<std::size_t>(a.k)] = static_cast<int>(b.t);
      tri[b.t].neighbour[static_cast<std::size_t>(b.k)] = static_cast<int>(a.t);
      break;
    }
  }
}

int corner_at(const std::vector<std::uint32_t>& vertex_of, std::size_t t, std::uint32_t v) {
  for (int k = 0; k < 3; ++k)
    if (vertex_of[3 * t + static_cast<std::size_t>(k)] == v) return k;
  return -1;
}

struct group {
  std::uint32_t vertex = 0;
  bool positive = false;
  std::vector<std::size_t> members;
};

// Step 4: the groups, each corner's group in group_of (−1: none).
std::vector<group> build_groups(const std::vector<std::uint32_t>& vertex_of, std::vector<triangle_info>& tri,
                                std::vector<int>& group_of) {
  std::vector<group> groups;
  std::vector<std::size_t> pending;
  for (std::size_t f = 0; f < tri.size(); ++f) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (tri[f].degenerate || tri[f].group_with_any || group_of[3 * f + i] >= 0) continue;
      const int g = static_cast<int>(groups.size());
      groups.push_back({vertex_of[3 * f + i], tri[f].positive, {}});
      pending.assign(1, f);
      while (!pending.empty()) {
        const std::size_t t = pending.back();
        pending.pop_back();
        const int k = corner_at(vertex_of, t, groups[static_cast<std::size_t>(g)].vertex);
        int& slot = group_of[3 * t + static_cast<std::size_t>(k)];
        if (slot >= 0) continue;  // in this group already, or in another
        if (tri[t].group_with_any && group_of[3 * t] < 0 && group_of[3 * t + 1] < 0 && group_of[3 * t + 2] < 0)
          tri[t].positive = groups[static_cast<std::size_t>(g)].positive;
        if (tri[t].positive != groups[static_cast<std::size_t>(g)].positive) continue;
        slot = g;
        groups[static_cast<std::size_t>(g)].members.push_back(t);
        for (int e : {k, (k + 2) % 3})  // the two edges at the vertex
          if (const int n = tri[t].neighbour[static_cast<std::size_t>(e)]; n >= 0)
            pending.push_back(static_cast<std::size_t>(n));
      }
    }
  }
  return groups;
}

}  // namespace

mikktspace_result mikktspace_tangents(const std::vector<tangent_corner>& corners) {
  const std::size_t triangles = corners.size() / 3;
  mikktspace_result r;
  r.corners.resize(corners.size());

  // 1. Weld equal corners into vertices.
  std::unordered_map<vertex_key, std::uint32_t, word_hash> ids;
  std::vector<std::uint32_t> vertex_of(corners.size());
  for (std::size_t c = 0; c < corners.size(); ++c)
    vertex_of[c] = ids.try_emplace(key_of(corners[c]), static_cast<std::uint32_t>(ids.size())).first->second;

  // 2. Per triangle: directions and orientation.
  std::vector<triangle_info> tri(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const tangent_corner* k = &corners[3 * t];
    triangle_info& ti = tri[t];
    ti.degenerate = k[0].position == k[1].position || k[0].position == k[2].position || k[1].position == k[2].position;
    const glm::vec3 e1 = k[1].position - k[0].position, e2 = k[2].position - k[0].position;
    const glm::vec2 d1 = k[1].uv - k[0].uv, d2 = k[2].uv - k[0].uv;
    const float area = d1.x * d2.y - d1.y * d2.x;  // twice the signed UV area
    // Solving e = du·Pu + dv·Pv for the two edges: area·Pu and area·Pv.
    const glm::vec3 os = e1 * d2.y - e2 * d1.y, ot = e2 * d1.x - e1 * d2.x;
    ti.positive = area > 0.0f;
    if (not_zero(area)) {
      const float s = ti.positive ? 1.0f : -1.0f, len_s = glm::length(os), len_t = glm::length(ot);
      if (not_zero(len_s)) ti.os = os * (s / len_s);
      if (not_zero(len_t)) ti.ot = ot * (s / len_t);
      ti.group_with_any = !(not_zero(len_s / std::fabs(area)) && not_zero(len_t / std::fabs(area)));
    }
    if (ti.group_with_any && !ti.degenerate) ++r.zero_uv_area_triangles;
  }

  // 3.–4. Neighbours and groups.
  find_neighbours(vertex_of, tri);
  std::vector<int> group_of(corners.size(), -1);
  const std::vector<group> groups = build_groups(vertex_of, tri, group_of);

  // 5. Each grouped corner's tangent from the members of its group that agree with its triangle.
  for (const group& g : groups) {
    const std::size_t first = g.members.front();
    const glm::vec3 n = corners[3 * first + static_cast<std::size_t>(corner_at(vertex_of, first, g.vertex))].normal;
    std::vector<glm::vec3> os(g.members.size()), ot(g.members.size());
    std::vector<float> angle(g.members.size());
    for (std::size_t m = 0; m < g.members.size(); ++m) {
      const std::size_t t = g.members[m];
      const int i = corner_at(vertex_of, t, g.vertex);
      os[m] = in_plane(tri[t].os, n);
      ot[m] = in_plane(tri[t].ot, n);
      const glm::vec3 p = corners[3 * t + static_cast<std::size_t>(i)].position;
      const glm::vec3 a = in_plane(corners[3 * t + static_cast<std::size_t>((i + 2) % 3)].position - p, n);
      const glm::vec3 b = in_plane(corners[3 * t + static_cast<std::size_t>((i + 1) % 3)].position - p, n);
      angle[m] = std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
    }
    constexpr float threshold_cos = -1.0f;  // cos 180°, genTangSpaceDefault's threshold, in float
    for (std::size_t m = 0; m < g.members.size(); ++m) {
      const std::size_t f = g.members[m];
      glm::vec3 sum(0.0f);
      for (std::size_t o = 0; o < g.members.size(); ++o) {
        const std::size_t t = g.members[o];
        if (tri[t].group_with_any) continue;  // joins the subgroup, adds nothing
        if (!tri[f].group_with_any &&
            !(glm::dot(os[m], os[o]) > threshold_cos && glm::dot(ot[m], ot[o]) > threshold_cos))
          continue;
        sum += angle[o] * os[o];
      }
      const std::size_t c = 3 * f + static_cast<std::size_t>(corner_at(vertex_of, f, g.vertex));
      const float sign = g.positive ? 1.0f : -1.0f;
      if (not_zero(sum)) {
        r.corners[c] = {glm::normalize(sum), sign};
      } else {
        r.corners[c] = {fallback_tangent(corners[c].normal), sign};
        ++r.fallback_corners;
      }
    }
  }

  // Corners no group reached (a zero-UV-area triangle without a grouped neighbour), then 6.
  // triangles with two equal positions: the first other triangle's corner at the vertex.
  std::vector<int> first_corner(ids.size(), -1);
  for (std::size_t c = 0; c < corners.size(); ++c) {
    if (tri[c / 3].degenerate) continue;
    if (first_corner[vertex_of[c]] < 0) first_corner[vertex_of[c]] = static_cast<int>(c);
    if (group_of[c] >= 0) continue;
    r.corners[c] = {fallback_tangent(corners[c].normal), -1.0f};
    ++r.fallback_corners;
  }
  for (std::size_t c = 0; c < corners.size(); ++c) {
    if (!tri[c / 3].degenerate) continue;
    if (const int from = first_corner[vertex_of[c]]; from >= 0) {
      r.corners[c] = r.corners[static_cast<std::size_t>(from)];
    } else {
      r.corners[c] = {fallback_tangent(corners[c].normal), -1.0f};
      ++r.fallback_corners;
    }
  }
  return r;
}

}  // namespace gsdot3::pipeline
