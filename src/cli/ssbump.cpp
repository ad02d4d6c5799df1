// gsdot3 ssbump — Source's two SSBump tools (seed 001, src/schemes/valve):
//   gsdot3 ssbump from-normal IN.png OUT.png [--rounding truncate|nearest] [--threads N]
//   gsdot3 ssbump from-height IN.png OUT.png --scale S [--rays 250] [--bias 0.55] [--tile 1|0]
//                 [--filter-radius 10] [--filter-threshold 0.00784314] [--height alpha|grey|auto] [--rounding ...]
// PNG in (any PNG, as RGBA by pipeline::read_png_rgba; 16-bit reduced to 8), RGB PNG out (written atomically). Progress
// on stderr.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "commands.hpp"
#include "pipeline/files.hpp"
#include "pipeline/image_io.hpp"
#include "valve/encode.hpp"
#include "valve/height2ssbump.hpp"

namespace gsdot3::cli {
namespace {

namespace v = gsdot3::valve;

struct ssbump_args {
  std::string in, out, rounding = "truncate", height = "auto";
  unsigned threads = 0;
  float scale = 0, bias = 0.55f, threshold = 2.0f / 255.0f;
  int rays = 250, tile = 1, radius = 10;
};

// "gsdot3 ssbump: <label> 42%" on stderr, at most twice a second, from any thread.
class progress {
 public:
  explicit progress(std::string label) : label_(std::move(label)) {}
  void operator()(double fraction) {
    std::lock_guard lock(m_);
    const auto now = std::chrono::steady_clock::now();
    if (fraction < 1.0 && now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    std::fprintf(stderr, "\rgsdot3 ssbump: %s %3.0f%%", label_.c_str(), fraction * 100.0);
    if (fraction >= 1.0) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

 private:
  std::string label_;
  std::mutex m_;
  std::chrono::steady_clock::time_point last_{};
};

v::quantise rounding_of(const std::string& s) {
  if (s == "truncate") return v::quantise::truncate;
  if (s == "nearest") return v::quantise::nearest;
  throw usage_error("--rounding: expected truncate (Source's writer) or nearest, got '" + s + "'");
}

pipeline::rgba_image read(const std::string& file) {
  try {
    return pipeline::read_png_rgba(file);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
}

void write(const std::string& file, const std::vector<v::texel>& texels, int w, int h) {
  pipeline::image img{w, h, 3, {}};
  img.data.reserve(texels.size() * 3);
  for (const auto& t : texels) img.data.insert(img.data.end(), {t.r, t.g, t.b});
  try {
    pipeline::write_png(file, img);
  } catch (const std::runtime_error& e) { throw usage_error(e.what()); }
}

void run_from_normal(const ssbump_args& a) {
  const auto q = rounding_of(a.rounding);
  const auto img = read(a.in);
  const std::size_t n = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  std::vector<v::texel> out(n);
  progress report("normal2ssbump " + a.in);
  std::atomic<int> next{0}, done{0};
  auto work = [&] {
    for (int y = next++; y < img.height; y = next++) {
      for (int x = 0; x < img.width; ++x) {
        const std::size_t i =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x);
        out[i] = v::ssbump_texel(v::normal2ssbump({img.rgba[4 * i], img.rgba[4 * i + 1], img.rgba[4 * i + 2]}), q);
      }
      report(static_cast<double>(++done) / img.height);
    }
  };
  const unsigned t = std::max(1U, a.threads ? a.threads : std::thread::hardware_concurrency());
  {
    std::vector<std::jthread> pool;
    for (unsigned k = 1; k < t; ++k) pool.emplace_back(work);
    work();
  }
  write(a.out, out, img.width, img.height);
}

void run_from_height(const ssbump_args& a) {
  const auto q = rounding_of(a.rounding);
  if (!(a.scale > 0))
    throw usage_error("--scale: the bump (elevation) scale must be > 0, got " + std::to_string(a.scale));
  if (a.rays < 0 || a.rays > 100000) throw usage_error("--rays: expected 0..100000, got " + std::to_string(a.rays));
  if (a.tile != 0 && a.tile != 1)
    throw usage_error("--tile: expected 1 (Source's 3×3 tiling) or 0, got " + std::to_string(a.tile));
  if (a.radius < 0 || a.radius > 64)
    throw usage_error("--filter-radius: expected 0..64, got " + std::to_string(a.radius));
  if (!(a.threshold > 0)) throw usage_error("--filter-threshold: must be > 0");
  if (a.height != "auto" && a.height != "alpha" && a.height != "grey")
    throw usage_error("--height: expected auto, alpha or grey, got '" + a.height + "'");
  const auto img = read(a.in);
  const bool alpha = a.height == "alpha" || (a.height == "auto" && img.has_alpha);
  if (a.height == "alpha" && !img.has_alpha)
    throw usage_error(a.in + ": --height alpha, but the image has no alpha channel");
  std::vector<float> h(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = static_cast<float>(img.rgba[4 * i + (alpha ? 3 : 0)]) / 255.0f;
  progress report("height2ssbump " + a.in);
  v::height2ssbump_options o;
  o.bump_scale = a.scale, o.rays = a.rays, o.origin_bias = a.bias, o.tile_reps = a.tile;
  o.filter_radius = a.radius, o.filter_threshold = a.threshold, o.threads = a.threads;
  o.progress = [&](double f) { report(f); };
  const auto weights = v::height2ssbump(h, img.width, img.height, o);
  std::vector<v::texel> out;
  out.reserve(weights.size());
  for (const auto& w : weights) out.push_back(v::ssbump_texel(w, q));
  write(a.out, out, img.width, img.height);
}

}  // namespace

void add_ssbump_command(CLI::App& app, context&) {
  auto* cmd =
      app.add_subcommand("ssbump", "Self-shadowed bump maps (seed 001): Source's normal2ssbump and height2ssbump");
  cmd->require_subcommand(1);
  auto args = std::make_shared<ssbump_args>();
  auto common = [&](CLI::App* s) {
    s->add_option("in", args->in, "Input PNG (8-bit)")->required();
    s->add_option("out", args->out, "Output RGB PNG")->required();
    s->add_option("--rounding", args->rounding, "8-bit writer: truncate (Source's PixRGBA8) or nearest")
        ->capture_default_str();
    s->add_option("--threads", args->threads, "Worker threads (0 = all cores)")->capture_default_str();
  };
  auto* n = cmd->add_subcommand(
      "from-normal",
      "normal2ssbump: each RGB8 normal texel N = 2t − 1 → D_i = saturate(N·B_i)² / Σ, with Source's float basis");
  common(n);
  n->callback([args] { run_from_normal(*args); });
  auto* h = cmd->add_subcommand(
      "from-height",
      "height2ssbump: bilateral pre-filter, 3×3 normals, ray-cast directional occlusion per basis vector");
  common(h);
  h->add_option("--scale", args->scale, "Bump (elevation) scale, Source's required second argument")->required();
  h->add_option("--rays", args->rays, "Rays per texel over the upper hemisphere (Source: -r, default 250)")
      ->capture_default_str();
  h->add_option("--bias", args->bias, "Ray origin raised above the surface (Source: 0.55)")->capture_default_str();
  h->add_option("--tile", args->tile, "1: trace against Source's 3×3 tiling (NREPS_TILE = 1); 0: the map alone")
      ->capture_default_str();
  h->add_option("--filter-radius", args->radius, "Bilateral pre-filter radius, 0 = off (Source: -f, default 10)")
      ->capture_default_str();
  h->add_option("--filter-threshold", args->threshold, "Bilateral edge threshold (Source: 2/255)")
      ->capture_default_str();
  h->add_option("--height", args->height, "Height from alpha (as Source), grey/red, or auto (alpha if present)")
      ->capture_default_str();
  h->callback([args] { run_from_height(*args); });
}

}  // namespace gsdot3::cli
