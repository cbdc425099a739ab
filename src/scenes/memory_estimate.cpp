#include "src/scenes/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/error.hpp"
#include "kernels/rolling/solver.hpp"
#include "src/io/available_memory.hpp"
#include "src/scenes/rolling_beam_settings.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/output_section.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/sensors_section.hpp"
#include "src/study/sections/signal_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/key_reader.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

namespace {

// The process itself: libraries, HDF5, FFTW wisdom (measured: 25-27 MiB peak for small studies,
// bench/engine/bench_memory_estimate.py).
constexpr double kBaseline = 28.0 * 1024 * 1024;

struct Item {
  double bytes;
  std::vector<std::string> keys;
  std::string what;
};

double key_real(const study::KeyReader& s, const std::string& k) { return s.has(k) ? s.real(k) : 0.0; }

std::vector<std::string> where(const study::KeyReader& s, const std::vector<std::string>& keys) {
  std::vector<std::string> out;
  for (const auto& k : keys) {
    if (!s.has(k)) continue;  // a term shared by scenes names only the keys this one has
    const auto dot = k.find('.');
    out.push_back("[" + k.substr(0, dot) + "] " + k.substr(dot + 1) + " = " + s.text(k));
  }
  return out;
}

// The ball's weight and E* as the scene derives them (ball_section), not a second formula.
double ball_weight(const study::KeyReader& s) { return study::BallSection::parse(s).weight(); }

double ball_e_star(const study::KeyReader& s) {
  const study::ModalBeamSection beam = study::ModalBeamSection::parse(s);
  return study::BallSection::parse(s).effective_modulus(beam.properties.youngs_modulus, beam.poisson);
}

// Contact solves on an nx x ny grid: the padded (2nx x 2ny) half-space operator and its FFT
// buffers, about five complex arrays (measured: 77 MB peak at 512^2).
Item contact_grid(const study::KeyReader& s) {
  const double nx = key_real(s, "surface.nx"), ny = key_real(s, "surface.ny");
  return {16.0 * 4.0 * nx * ny * 5.0, where(s, {"surface.nx", "surface.ny"}), "contact solver grid"};
}

// The solver's square window and the rough strip it slides along, on the grid the stage uses
// (derived from the contact radius where the study leaves it open).
Item blocked_force_window(const study::KeyReader& s) {
  const double radius = study::BallSection::parse(s).radius, weight = ball_weight(s), e_star = ball_e_star(s);
  const auto g = stiffness::blocked_force_geometry(
      study::BlockedForceSection::parse(s), study::StripSurfaceSection::parse(s), texture_io::study_psd(s), radius,
      e_star, weight, study::BallSection::parse(s).speed / study::SignalSection::parse(s).sample_rate);
  const double w = static_cast<double>(g.window), strip = static_cast<double>(g.nx) * static_cast<double>(g.ny);
  return {16.0 * 4.0 * w * w * 5.0 + 8.0 * strip * 4.0,
          where(s, {"blocked_force.window", "surface.ny", "surface.spacing"}),
          "blocked-force contact window (" + std::to_string(g.window) + " cells) and strip (" + std::to_string(g.ny) +
              " x " + std::to_string(g.nx) + " cells)"};
}

// Isotropic surfaces kept for the output (count x ny x nx) plus the generator's complex FFT grid.
Item surfaces(const study::KeyReader& s, double count) {
  const double nx = key_real(s, "surface.nx"), ny = key_real(s, "surface.ny");
  return {8.0 * nx * ny * (count + 6.0), where(s, {"surface.nx", "surface.ny", "surface.count"}), "isotropic surfaces"};
}

// The ensemble's own storage: one chunk's rows (chunk_size x values), the partial sums the pairwise
// tree keeps (at most log2 of the chunk count, and log2 of the chunk size while a chunk is added,
// each [sum, sum of squares]) and the copies of the final reduction. It no longer grows with the
// number of chunks (TreeAccumulator). Values per realisation: PSD and band rows of each output row.
Item chunk_sums(const study::KeyReader& s, double rows) {
  const double nf = key_real(s, "spectrum.segment") / 2.0 + 1.0;
  const double values = 2.0 * rows * (nf + 40.0) + 8.0;
  const double K = std::max(key_real(s, "study.realisations"), 1.0),
               C = std::max(key_real(s, "ensemble.chunk_size"), 1.0);
  const double kept = std::log2(std::max(K / C, 1.0)) + std::log2(C) + 6.0;
  return {8.0 * values * (C + 2.0 * kept), where(s, {"ensemble.chunk_size", "spectrum.segment", "sensors.positions"}),
          "one chunk of realisations and the partial sums of the ensemble"};
}

// Welch record length after skip_start, and its segments (as spectral::WelchPlan counts them).
struct WelchShape {
  double nf = 0.0, segments = 0.0, lags = 0.0;
};
WelchShape welch_shape(const study::KeyReader& s, double samples) {
  const double L = key_real(s, "spectrum.segment");
  const double hop = std::max(1.0, L - std::floor(key_real(s, "spectrum.overlap") * L));
  const double n = samples - std::ceil(key_real(s, "spectrum.skip_start") * key_real(s, "signal.sample_rate"));
  return {L / 2.0 + 1.0, std::max(1.0, std::floor((n - L) / hop) + 1.0), std::ceil(L / hop)};
}

// The linearised reference (kernels/beam/linear_reference.cpp): the sensors' cross-spectra, one per
// sensor pair, summed per Welch segment group on the fine grid (refine 8) and smoothed per bin:
// (16 x 8 + 16) bytes per pair, group and bin, plus the dof of the mean over all pairs.
Item linear_reference(const study::KeyReader& s, double sensors, double samples) {
  const WelchShape w = welch_shape(s, samples);
  const double pairs = sensors * (sensors + 1.0) / 2.0, groups = w.segments * w.lags;
  return {pairs * groups * w.nf * (16.0 * 8.0 + 16.0 * 2.0), where(s, {"sensors.positions", "output.reference"}),
          "linearised reference, one cross-spectrum per sensor pair (" + std::to_string(static_cast<long long>(pairs)) +
              " pairs; [output] reference = false skips it)"};
}

// law = path: P(delta_j, xi_k) rows of every approach (position, force, stiffness per row, the
// table and its interpolation copy), the strip, and one contact solver window per thread.
Item path_table(const study::KeyReader& s, double threads) {
  const double weight = ball_weight(s);
  const auto g = stiffness::path_table_geometry(study::PathTableSection::parse(s), study::BlockedForceSection::parse(s),
                                                study::StripSurfaceSection::parse(s), texture_io::study_psd(s),
                                                study::BallSection::parse(s).radius, ball_e_star(s), weight,
                                                key_real(s, "ball.end") - key_real(s, "ball.start"));
  const double cells = static_cast<double>(g.approaches) * static_cast<double>(g.positions);
  const double w = static_cast<double>(g.window);
  return {
      8.0 * cells * 6.0 + 8.0 * static_cast<double>(g.nx) * static_cast<double>(g.ny) * 4.0 +
          threads * 16.0 * 4.0 * w * w * 5.0,
      where(s, {"path_table.approaches", "path_table.step", "surface.ny"}),
      "path table, " + std::to_string(g.approaches) + " approaches x " + std::to_string(g.positions) + " positions"};
}

// rolling-beam keeps every recorded state (positions, velocities, accelerations, angular
// velocities and accelerations, rotations; contacts; energies) and copies one field at the write;
// the Newton system is a band matrix of 6 dofs per node.
std::vector<Item> rolling_beam(const study::KeyReader& s) {
  const RollingBeamSettings r = read_rolling_beam_settings(s);
  const double nodes = static_cast<double>(r.model.X.size()), nn = static_cast<double>(r.record.size());
  const double nc = static_cast<double>(r.model.contacts.size());
  const double records = std::floor(r.run.t_end / r.run.dt / std::max(r.run.record_every, 1)) + 2.0;
  // Nine per-record vectors, each a 24-byte header and a heap block (about 24 bytes of overhead).
  const double per_record = nn * (5.0 * 24.0 + 72.0) + 9.0 * 48.0 +
                            nc * static_cast<double>(sizeof(rolling::ContactOutput)) +
                            static_cast<double>(sizeof(rolling::Energies)) + 8.0;
  const double write_copy = records * (nn * 72.0 + nc * 9.0 * 8.0);
  return {{records * per_record + write_copy,
           where(s, {"analysis.dt", "analysis.t_end", "analysis.record_every", "output.nodes", "beam.elements"}),
           "time history, " + std::to_string(static_cast<long long>(records)) + " recorded states of " +
               std::to_string(static_cast<long long>(nn)) + " nodes"},
          {nodes * 6.0 * 8.0 * 400.0, where(s, {"beam.elements"}),
           "beam model and its band Newton system, " + std::to_string(static_cast<long long>(nodes)) + " nodes"}};
}

std::vector<Item> items(const study::KeyReader& s, int threads) {
  const std::string scene = s.scene();
  const double t = threads;
  std::vector<Item> out;
  if (scene == "random-oscillator") {
    // Per thread: force, acceleration and the two uniform draws (3 n doubles); shared: the
    // synthesiser's FFT (measured: 0.91 GB peak at n = 1e7 on 2 threads).
    const double n = key_real(s, "signal.sample_rate") * key_real(s, "signal.duration");
    out.push_back({8.0 * n * (3.0 * t + 5.0), where(s, {"signal.sample_rate", "signal.duration"}),
                   "one realisation's record per thread"});
    out.push_back(chunk_sums(s, 1.0));
  } else if (scene == "texture") {
    const double samples = key_real(s, "lines.length") / std::max(key_real(s, "lines.spacing"), 1e-300);
    out.push_back({8.0 * samples * (2.0 * key_real(s, "lines.count") + 6.0),
                   where(s, {"lines.count", "lines.length", "lines.spacing"}), "line textures"});
    out.push_back(surfaces(s, key_real(s, "surface.count")));
  } else if (scene == "stiffness") {
    out.push_back(contact_grid(s));
  } else if (scene == "ball-on-beam") {
    const double record = (key_real(s, "ball.end") - key_real(s, "ball.start")) /
                          std::max(key_real(s, "ball.speed"), 1e-300) * key_real(s, "signal.sample_rate");
    const double sensors = static_cast<double>(study::SensorsSection::parse(s).positions.size());
    out.push_back({8.0 * record * (sensors + 6.0) * (t + 1.0),
                   where(s, {"ball.start", "ball.end", "ball.speed", "signal.sample_rate"}),
                   "time records per thread"});
    out.push_back(chunk_sums(s, sensors + 4.0));
    const double histories = key_real(s, "output.time_histories");
    if (histories > 0)
      out.push_back(
          {8.0 * record * (sensors + 4.0) * histories, where(s, {"output.time_histories"}), "stored time histories"});
    const study::ContactSection contact = study::ContactSection::parse(s);
    const std::string& law = contact.law;
    if ((law == "table" || law == "literal") && study::StiffnessSection::parse(s).rough) out.push_back(contact_grid(s));
    if (law == "linearised" && contact.blocked_force == "solver") out.push_back(blocked_force_window(s));
    if (law == "linearised" && study::OutputSection::parse(s).reference)
      out.push_back(linear_reference(s, sensors, record));
    if (law == "path") out.push_back(path_table(s, t));
  } else if (scene == "rolling-pipe") {
    if (!study::PipeRoughnessSection::parse(s).line) {
      // One isotropic floor per realisation and thread, plus the generator's complex FFT grid.
      const double nx = key_real(s, "surface.nx"), ny = key_real(s, "surface.ny");
      out.push_back({8.0 * nx * ny * (t + 10.0), where(s, {"surface.nx", "surface.ny"}), "rough floor per thread"});
    }
    out.push_back(chunk_sums(s, static_cast<double>(study::PipeSensorsSection::parse(s).positions.size()) + 2.0));
  } else if (scene == "rolling-beam") {
    for (auto& it : rolling_beam(s)) out.push_back(std::move(it));
  }
  return out;
}

}  // namespace

MemoryEstimate estimate_memory(const study::KeyReader& s, int threads) {
  MemoryEstimate e;
  e.bytes = kBaseline;
  double largest = -1.0;
  for (const auto& it : items(s, threads)) {
    e.bytes += it.bytes;
    e.terms.emplace_back(it.what, it.bytes);
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

void check_memory(const study::KeyReader& s, int threads, bool force) {
  const MemoryEstimate e = estimate_memory(s, threads);
  const double available = io::available_memory();
  if (force || !(e.bytes > available)) return;
  std::string keys;
  for (const auto& k : e.keys) keys += (keys.empty() ? "" : ", ") + k;
  throw config_error(
      s.file() + ": the study needs an estimated " + format_bytes(e.bytes) + " of memory (largest: " + e.what +
      ", from " + keys + ", " + std::to_string(threads) + " thread(s)), but only " + format_bytes(available) +
      " is available; allowed: a smaller value of these keys, fewer threads (OMP_NUM_THREADS), or --force "
      "to try anyway");
}

}  // namespace rollspec::scenes
