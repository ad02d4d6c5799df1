// pipeline/prepare.cpp — the vertex stage (what the paper's VU1 program does), in float.
#include "pipeline/prepare.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>

namespace gsdot3::pipeline {

namespace {

struct screen_vertex {
  bool ok = false;
  xy124 xy;
  std::int32_t z = 0;
};

// The vertices of m in window 12.4 coordinates and 24-bit depth (ok: drawable).
std::vector<screen_vertex> project(const mesh& m, const glm::mat4& mvp, int width, int height) {
  std::vector<screen_vertex> sv(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const glm::vec4 c = mvp * glm::vec4(m.vertices[i].position, 1.0f);
    if (!(c.w > 1e-3f)) continue;
    const float x = (c.x / c.w * 0.5f + 0.5f) * static_cast<float>(width);
    const float y = (0.5f - c.y / c.w * 0.5f) * static_cast<float>(height);
    const float z = std::clamp((1.0f - c.z / c.w) * 0.5f, 0.0f, 1.0f);
    const float lim = xy_offset_pixels - 1.0f;
    if (!(std::fabs(x) < lim && std::fabs(y) < lim)) continue;
    sv[i] = {true,
             {static_cast<std::int32_t>(std::lround(x * 16.0f)), static_cast<std::int32_t>(std::lround(y * 16.0f))},
             static_cast<std::int32_t>(std::lround(z * 16777215.0f))};
  }
  return sv;
}

// m's front-facing, drawable triangles, with UVs in 12.4 texels of a tw × th texture; the others
// counted in culled / dropped.
std::vector<prepared_triangle> set_up(const mesh& m, const std::vector<screen_vertex>& sv, int tex_w, int tex_h,
                                      int& culled, int& dropped) {
  std::vector<prepared_triangle> out;
  const float tw = static_cast<float>(tex_w) * 16.0f, th = static_cast<float>(tex_h) * 16.0f;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    if (!sv[tri[0]].ok || !sv[tri[1]].ok || !sv[tri[2]].ok) {
      ++dropped;
      continue;
    }
    prepared_triangle pt;
    pt.vertex = tri;
    pt.layer = layer_of(m, t);
    pt.setup = setup_triangle({sv[tri[0]].xy, sv[tri[1]].xy, sv[tri[2]].xy});
    if (!pt.setup.front) {
      ++culled;
      continue;
    }
    pt.z24 = {sv[tri[0]].z, sv[tri[1]].z, sv[tri[2]].z};
    pt.z = make_plane(pt.setup.v, pt.z24, 0, 0xFFFFFF);
    // UVs in 12.4 texels; the whole triangle moved by whole repeats so its smallest U and V are in
    // the first repeat (REPEAT wrapping makes that invisible), as a VU1 program would.
    std::array<glm::vec2, 3> uv{};
    for (int k = 0; k < 3; ++k) uv[k] = m.vertices[tri[k]].uv * glm::vec2(tw, th);
    const float su = std::floor(std::min({uv[0].x, uv[1].x, uv[2].x}) / tw) * tw;
    const float sv2 = std::floor(std::min({uv[0].y, uv[1].y, uv[2].y}) / th) * th;
    for (int k = 0; k < 3; ++k)
      pt.uv16[k] = {static_cast<std::int32_t>(std::lround(std::min(uv[k].x - su, 16383.0f))),
                    static_cast<std::int32_t>(std::lround(std::min(uv[k].y - sv2, 16383.0f)))};
    out.push_back(pt);
  }
  return out;
}

}  // namespace

prepared_scene prepare(const scene& s, float yaw_degrees, bool half_vectors) {
  prepared_scene ps;
  ps.width = s.width;
  ps.height = s.height;
  const glm::mat4 model = glm::rotate(glm::mat4(1.0f), glm::radians(yaw_degrees), glm::vec3(0, 1, 0));
  const glm::mat4 view = glm::lookAt(s.view.eye, s.view.target, glm::vec3(0, 1, 0));
  const glm::mat4 proj = glm::perspective(glm::radians(s.view.fov_y_degrees),
                                          static_cast<float>(s.width) / static_cast<float>(s.height), 0.1f, 100.0f);
  const glm::mat4 mvp = proj * view * model;
  const auto& verts = s.model.vertices;

  // Light vectors in tangent space, from the light positions (directions, for a directional light)
  // taken into object space.
  const glm::mat4 to_object = glm::inverse(model);
  const glm::vec3 eye = glm::vec3(to_object * glm::vec4(s.view.eye, 1.0f));
  auto light_position = [&](const scene_light& l) {
    return glm::vec3(to_object * glm::vec4(l.position, l.kind == light_kind::directional ? 0.0f : 1.0f));
  };
  auto tolight = [](const scene_light& l, const glm::vec3& lp, const glm::vec3& p) {
    return glm::normalize(l.kind == light_kind::directional ? lp : lp - p);
  };
  ps.lights.resize(s.lights.size());
  ps.spots.resize(s.lights.size());
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    if (s.lights[l].kind == light_kind::spot) ps.spots[l] = spot_coordinates(s.lights[l], to_object, s.model);
    const glm::vec3 lp = light_position(s.lights[l]);
    ps.lights[l].resize(verts.size());
    for (std::size_t i = 0; i < verts.size(); ++i) {
      const vertex& v = verts[i];
      const glm::vec3 L = tolight(s.lights[l], lp, v.position);
      const glm::vec3 H = half_vectors ? glm::normalize(L + glm::normalize(eye - v.position)) : L;
      ps.lights[l][i].T =
          glm::normalize(glm::vec3(glm::dot(H, v.tangent), glm::dot(H, v.bitangent), glm::dot(H, v.normal)));
      ps.lights[l][i].fade = std::clamp(6.0f * glm::dot(v.normal, L), 0.0f, 1.0f);
    }
  }
  ps.triangles = set_up(s.model, project(s.model, mvp, s.width, s.height), s.normals.width, s.normals.height,
                        ps.culled_back, ps.dropped_outside);
  const std::size_t n_layers = layers(s.normals);
  for (std::uint16_t k : s.model.layer)
    if (k >= n_layers)
      throw std::invalid_argument("a triangle samples normal-map layer " + std::to_string(k) + " of " +
                                  std::to_string(n_layers));
  std::vector<std::uint32_t> count(n_layers + 1, 0);
  for (const prepared_triangle& t : ps.triangles) ++count[t.layer + 1u];
  std::stable_sort(ps.triangles.begin(), ps.triangles.end(),
                   [](const prepared_triangle& a, const prepared_triangle& b) { return a.layer < b.layer; });
  for (std::size_t k = 0; k < n_layers; ++k) {
    count[k + 1] += count[k];
    ps.layers.push_back({count[k], count[k + 1]});
  }

  // Step 5's geometry: Lambert per vertex, as a VU1 lighting program for Gouraud shading would.
  ps.plain_light.assign(s.plain.vertices.size(), glm::vec3(s.ambient[0], s.ambient[1], s.ambient[2]));
  for (const scene_light& l : s.lights) {
    const glm::vec3 lp = light_position(l);
    const std::vector<spot_vertex> spot =
        l.kind == light_kind::spot ? spot_coordinates(l, to_object, s.plain) : std::vector<spot_vertex>{};
    for (std::size_t i = 0; i < s.plain.vertices.size(); ++i) {
      const vertex& v = s.plain.vertices[i];
      float k = std::max(glm::dot(v.normal, tolight(l, lp, v.position)), 0.0f);
      if (!spot.empty())
        k *= spot[i].front ? static_cast<float>(spot_intensity(spot[i].S / spot[i].Q, spot[i].T / spot[i].Q)) : 0.0f;
      ps.plain_light[i] += glm::vec3(l.colour[0], l.colour[1], l.colour[2]) * k;
    }
  }
  int plain_culled = 0, plain_dropped = 0;
  ps.plain = set_up(s.plain, project(s.plain, mvp, s.width, s.height), s.diffuse.width, s.diffuse.height, plain_culled,
                    plain_dropped);
  return ps;
}

}  // namespace gsdot3::pipeline
