#include "src/scenes/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/error.hpp"
#include "kernels/contact/geometry.hpp"
#include "src/io/available_memory.hpp"
#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/study/study.hpp"

namespace rollspec::scenes {

namespace {

constexpr double kBaseline = 64.0 * 1024 * 1024;  // the process itself: libraries, HDF5, FFTW wisdom

struct Item {
  double bytes;
  std::vector<std::string> keys;
  std::string what;
};

double key_real(const study::Study& s, const std::string& k) { return s.has(k) ? s.real(k) : 0.0; }

std::vector<std::string> where(const study::Study& s, const std::vector<std::string>& keys) {
  std::vector<std::string> out;
  for (const auto& k : keys) {
    const auto dot = k.find('.');
    out.push_back("[" + k.substr(0, dot) + "] " + k.substr(dot + 1) + " = " + s.text(k));
  }
  return out;
}

// Contact solves on an nx x ny grid: the padded (2nx x 2ny) half-space operator and its FFT
// buffers, about five complex arrays (measured: 77 MB peak at 512^2).
Item contact_grid(const study::Study& s) {
  const double nx = key_real(s, "surface.nx"), ny = key_real(s, "surface.ny");
  return {16.0 * 4.0 * nx * ny * 5.0, where(s, {"surface.nx", "surface.ny"}), "contact solver grid"};
}

// The solver's square window and the rough strip it slides along, on the grid the stage uses
// (derived from the contact radius where the study leaves it open).
Item blocked_force_window(const study::Study& s) {
  const double radius = s.real("ball.radius");
  const double weight = 4.0 / 3.0 * M_PI * radius * radius * radius * s.real("ball.density") * s.real("ball.gravity");
  const double e_star = contact::effective_modulus(s.real("ball.youngs_modulus"), s.real("ball.poisson"),
                                                   s.real("beam.youngs_modulus"), s.real("beam.poisson"));
  const auto g = stiffness::blocked_force_geometry(s, radius, e_star, weight, s.real("ball.speed") / s.real("signal.sample_rate"));
  const double w = static_cast<double>(g.window), strip = static_cast<double>(g.nx) * static_cast<double>(g.ny);
  return {16.0 * 4.0 * w * w * 5.0 + 8.0 * strip * 4.0, where(s, {"blocked_force.window", "surface.ny", "surface.spacing"}),
          "blocked-force contact window (" + std::to_string(g.window) + " cells) and strip (" + std::to_string(g.ny) +
              " x " + std::to_string(g.nx) + " cells)"};
}

// Isotropic surfaces kept for the output (count x ny x nx) plus the generator's complex FFT grid.
Item surfaces(const study::Study& s, double count) {
  const double nx = key_real(s, "surface.nx"), ny = key_real(s, "surface.ny");
  return {8.0 * nx * ny * (count + 6.0), where(s, {"surface.nx", "surface.ny", "surface.count"}), "isotropic surfaces"};
}

std::vector<Item> items(const study::Study& s, int threads) {
  const std::string scene = s.scene();
  const double t = threads;
  std::vector<Item> out;
  if (scene == "random-oscillator") {
    // Per thread: force, acceleration and the two uniform draws (3 n doubles); shared: the
    // synthesiser's FFT (measured: 0.91 GB peak at n = 1e7 on 2 threads).
    const double n = key_real(s, "signal.sample_rate") * key_real(s, "signal.duration");
    out.push_back({8.0 * n * (3.0 * t + 5.0), where(s, {"signal.sample_rate", "signal.duration"}),
                   "one realisation's record per thread"});
  } else if (scene == "texture") {
    const double samples = key_real(s, "lines.length") / std::max(key_real(s, "lines.spacing"), 1e-300);
    out.push_back({8.0 * samples * (2.0 * key_real(s, "lines.count") + 6.0),
                   where(s, {"lines.count", "lines.length", "lines.spacing"}), "line textures"});
    out.push_back(surfaces(s, key_real(s, "surface.count")));
  } else if (scene == "stiffness") {
    out.push_back(contact_grid(s));
  } else if (scene == "ball-on-beam") {
    const double record = (key_real(s, "ball.end") - key_real(s, "ball.start")) / std::max(key_real(s, "ball.speed"), 1e-300) *
                          key_real(s, "signal.sample_rate");
    const double sensors = static_cast<double>(s.list("sensors.positions").size());
    out.push_back({8.0 * record * (sensors + 6.0) * (t + 1.0),
                   where(s, {"ball.start", "ball.end", "ball.speed", "signal.sample_rate"}), "time records per thread"});
    const std::string law = s.text("contact.law");
    if ((law == "table" || law == "literal") && s.text("stiffness.surface") == "rough") out.push_back(contact_grid(s));
    if (law == "linearised" && s.text("contact.blocked_force") == "solver") out.push_back(blocked_force_window(s));
  } else if (scene == "rolling-pipe" && s.text("roughness.kind") != "line") {
    // One isotropic floor per realisation and thread, plus the generator's complex FFT grid.
    const double nx = key_real(s, "surface.nx"), ny = key_real(s, "surface.ny");
    out.push_back({8.0 * nx * ny * (t + 10.0), where(s, {"surface.nx", "surface.ny"}), "rough floor per thread"});
  }
  return out;
}

}  // namespace

MemoryEstimate estimate_memory(const study::Study& s, int threads) {
  MemoryEstimate e;
  e.bytes = kBaseline;
  double largest = -1.0;
  for (const auto& it : items(s, threads)) {
    e.bytes += it.bytes;
    if (it.bytes > largest) {
      largest = it.bytes;
      e.keys = it.keys;
      e.what = it.what;
    }
  }
  return e;
}

std::string format_bytes(double b) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (b >= 1024.0 && u < 5) b /= 1024.0, ++u;
  char buf[32];
  std::snprintf(buf, sizeof buf, u ? "%.3g %s" : "%.0f %s", b, units[u]);
  return buf;
}

void check_memory(const study::Study& s, int threads, bool force) {
  const MemoryEstimate e = estimate_memory(s, threads);
  const double available = io::available_memory();
  if (force || !(e.bytes > available)) return;
  std::string keys;
  for (const auto& k : e.keys) keys += (keys.empty() ? "" : ", ") + k;
  throw config_error(s.file() + ": the study needs an estimated " + format_bytes(e.bytes) + " of memory (largest: " + e.what +
                     ", from " + keys + ", " + std::to_string(threads) + " thread(s)), but only " + format_bytes(available) +
                     " is available; allowed: a smaller value of these keys, fewer threads (OMP_NUM_THREADS), or --force "
                     "to try anyway");
}

}  // namespace rollspec::scenes
