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
#include "src/stiffness/blocked_force_table.hpp"
#include "src/io/number_text.hpp"
#include "src/scenes/ball_on_beam_sections.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/lines_section.hpp"
#include "src/study/sections/random_oscillator_sections.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/surface_grid_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

namespace {

// The process itself: libraries, HDF5, FFTW wisdom (measured: 25-27 MiB peak for small studies,
// bench/engine/bench_memory_estimate.py).
constexpr double kBaseline = 28.0 * 1024 * 1024;

using Item = MemoryItem;

// "[section] key = value", the value as the typed section holds it.
std::string key_text(const char* section, const char* key, double value) {
  return std::string("[") + section + "] " + key + " = " + io::number_text(value);
}
std::string key_text(const char* section, const char* key, const std::string& value) {
  return std::string("[") + section + "] " + key + " = " + value;
}
std::string positions_text(const char* section, const std::vector<double>& positions) {
  std::string v;
  for (double x : positions) v += (v.empty() ? "" : ", ") + io::number_text(x);
  return key_text(section, "positions", v);
}

// Contact solves on an nx x ny grid: the padded (2nx x 2ny) half-space operator and its FFT
// buffers, about five complex arrays (measured: 77 MB peak at 512^2).
Item contact_grid(double nx, double ny) {
  return {16.0 * 4.0 * nx * ny * 5.0,
          {key_text("surface", "nx", nx), key_text("surface", "ny", ny)},
          "contact solver grid"};
}

// E* of the ball on the beam, as the scene derives it (ball_section), not a second formula.
double ball_e_star(const BallOnBeamSections& b) {
  return b.ball.effective_modulus(b.beam.properties.youngs_modulus, b.beam.poisson);
}

// The solver's square window and the rough strip it slides along, on the grid the stage uses
// (derived from the contact radius where the study leaves it open).
stiffness::BlockedForceGeometry blocked_force_grid(const BallOnBeamSections& b) {
  return stiffness::blocked_force_geometry(b.blocked_force, b.strip_surface, b.texture_psd, b.ball.radius,
                                           ball_e_star(b), b.ball.weight(), b.ball.speed / b.signal.sample_rate);
}

Item blocked_force_window(const BallOnBeamSections& b) {
  const auto g = blocked_force_grid(b);
  const double w = static_cast<double>(g.window), strip = static_cast<double>(g.nx) * static_cast<double>(g.ny);
  return {16.0 * 4.0 * w * w * 5.0 + 8.0 * strip * 4.0,
          {key_text("blocked_force", "window", static_cast<double>(b.blocked_force.window)),
           key_text("surface", "ny", static_cast<double>(b.strip_surface.ny)),
           key_text("surface", "spacing", b.strip_surface.spacing)},
          "blocked-force contact window (" + std::to_string(g.window) + " cells) and strip (" + std::to_string(g.ny) +
              " x " + std::to_string(g.nx) + " cells)"};
}

// Isotropic surfaces kept for the output (count x ny x nx) plus the generator's complex FFT grid.
Item surfaces(const study::SurfaceSection& f) {
  const double nx = static_cast<double>(f.nx), ny = static_cast<double>(f.ny), count = static_cast<double>(f.count);
  return {8.0 * nx * ny * (count + 6.0),
          {key_text("surface", "nx", nx), key_text("surface", "ny", ny), key_text("surface", "count", count)},
          "isotropic surfaces"};
}

// The ensemble's own storage: one chunk's rows (chunk_size x values), the partial sums the pairwise
// tree keeps (at most log2 of the chunk count, and log2 of the chunk size while a chunk is added,
// each [sum, sum of squares]) and the copies of the final reduction. It no longer grows with the
// number of chunks (TreeAccumulator). Values per realisation: PSD and band rows of each output row.
// `sensors`: the scene's sensor key, if it has one.
Item chunk_sums(const study::StudySection& st, const study::EnsembleSection& en, const study::SpectrumSection& sp,
                double rows, std::vector<std::string> sensors) {
  const double nf = static_cast<double>(sp.segment) / 2.0 + 1.0;
  const double values = 2.0 * rows * (nf + 40.0) + 8.0;
  const double K = std::max(static_cast<double>(st.realisations), 1.0),
               C = std::max(static_cast<double>(en.chunk_size), 1.0);
  const double kept = std::log2(std::max(K / C, 1.0)) + std::log2(C) + 6.0;
  std::vector<std::string> keys = {key_text("ensemble", "chunk_size", C),
                                   key_text("spectrum", "segment", static_cast<double>(sp.segment))};
  for (auto& k : sensors) keys.push_back(std::move(k));
  return {8.0 * values * (C + 2.0 * kept), keys, "one chunk of realisations and the partial sums of the ensemble"};
}

// Welch record length after skip_start, and its segments (as spectral::WelchPlan counts them).
struct WelchShape {
  double nf = 0.0, segments = 0.0, lags = 0.0;
};
WelchShape welch_shape(const study::SpectrumSection& sp, double sample_rate, double samples) {
  const double L = static_cast<double>(sp.segment);
  const double hop = std::max(1.0, L - std::floor(sp.overlap * L));
  const double n = samples - std::ceil(sp.skip_start * sample_rate);
  return {L / 2.0 + 1.0, std::max(1.0, std::floor((n - L) / hop) + 1.0), std::ceil(L / hop)};
}

// The linearised reference (kernels/beam/linear_reference.cpp): the sensors' cross-spectra, one per
// sensor pair, summed per Welch segment group on the fine grid (refine 8) and smoothed per bin:
// (16 x 8 + 16) bytes per pair, group and bin, plus the dof of the mean over all pairs.
Item linear_reference(const BallOnBeamSections& b, double sensors, double samples) {
  const WelchShape w = welch_shape(b.spectrum, b.signal.sample_rate, samples);
  const double pairs = sensors * (sensors + 1.0) / 2.0, groups = w.segments * w.lags;
  return {pairs * groups * w.nf * (16.0 * 8.0 + 16.0 * 2.0),
          {positions_text("sensors", b.sensors.positions),
           key_text("output", "reference", b.output.reference ? "true" : "false")},
          "linearised reference, one cross-spectrum per sensor pair (" + std::to_string(static_cast<long long>(pairs)) +
              " pairs; [output] reference = false skips it)"};
}

// law = path: P(delta_j, xi_k) rows of every approach (position, force, stiffness per row, the
// table and its interpolation copy), the strip, and one contact solver window per thread.
Item path_table(const BallOnBeamSections& b, double threads) {
  const auto g =
      stiffness::path_table_geometry(b.path_table, b.blocked_force, b.strip_surface, b.texture_psd, b.ball.radius,
                                     ball_e_star(b), b.ball.weight(), b.ball.end - b.ball.start);
  const double cells = static_cast<double>(g.approaches) * static_cast<double>(g.positions);
  const double w = static_cast<double>(g.window);
  return {
      8.0 * cells * 6.0 + 8.0 * static_cast<double>(g.nx) * static_cast<double>(g.ny) * 4.0 +
          threads * 16.0 * 4.0 * w * w * 5.0,
      {key_text("path_table", "approaches", static_cast<double>(b.path_table.approaches)),
       key_text("path_table", "step", static_cast<double>(b.path_table.step)),
       key_text("surface", "ny", static_cast<double>(b.strip_surface.ny))},
      "path table, " + std::to_string(g.approaches) + " approaches x " + std::to_string(g.positions) + " positions"};
}

std::vector<Item> ball_on_beam(const BallOnBeamSections& b, double threads) {
  std::vector<Item> out;
  const double record = (b.ball.end - b.ball.start) / std::max(b.ball.speed, 1e-300) * b.signal.sample_rate;
  const double sensors = static_cast<double>(b.sensors.positions.size());
  out.push_back({8.0 * record * (sensors + 6.0) * (threads + 1.0),
                 {key_text("ball", "start", b.ball.start), key_text("ball", "end", b.ball.end),
                  key_text("ball", "speed", b.ball.speed), key_text("signal", "sample_rate", b.signal.sample_rate)},
                 "time records per thread"});
  out.push_back(
      chunk_sums(b.study, b.ensemble, b.spectrum, sensors + 4.0, {positions_text("sensors", b.sensors.positions)}));
  if (b.stiffness.table_jackknife) {  // D-30: the N sub-tables' scenes run together, each its own records and sums
    const bool surfaces = b.contact.uses_stiffness_table() && b.stiffness.rough;
    const bool segments = b.contact.blocked_solver();  // else strips
    const double n = static_cast<double>(surfaces   ? b.stiffness.realisations
                                         : segments ? stiffness::f0_segments(blocked_force_grid(b)).segments
                                                    : b.equivalent_roughness.strips);
    out.push_back(
        {n * (out[out.size() - 2].bytes + out.back().bytes),
         {surfaces   ? key_text("stiffness", "realisations", n)
          : segments ? "[blocked_force] segment, strip_length (" + io::exact_text(n) + " Welch segments of F0)"
                     : key_text("equivalent_roughness", "strips", n),
          "[stiffness] table_error = jackknife"},
         "the sub-tables' scenes (time records per thread, chunk sums)"});
  }
  const double histories = static_cast<double>(b.output.time_histories);
  if (histories > 0)
    out.push_back({8.0 * record * (sensors + 4.0) * histories,
                   {key_text("output", "time_histories", histories)},
                   "stored time histories"});
  switch (b.contact.law) {
    case study::ContactLaw::table:
    case study::ContactLaw::literal:
      if (b.stiffness.rough)
        out.push_back(contact_grid(static_cast<double>(b.strip_surface.nx), static_cast<double>(b.strip_surface.ny)));
      break;
    case study::ContactLaw::linearised:
      if (b.contact.blocked_solver()) out.push_back(blocked_force_window(b));
      if (b.output.reference) out.push_back(linear_reference(b, sensors, record));
      break;
    case study::ContactLaw::path:
      out.push_back(path_table(b, threads));
      break;
    case study::ContactLaw::hertz:
      break;
  }
  return out;
}

// rolling-beam keeps every recorded state (positions, velocities, accelerations, angular
// velocities and accelerations, rotations; contacts; energies) and copies one field at the write;
// the Newton system is a band matrix of 6 dofs per node.
std::vector<Item> rolling_beam(const RollingBeamSettings& r) {
  const double nodes = static_cast<double>(r.model.X.size()), nn = static_cast<double>(r.record.size());
  const double nc = static_cast<double>(r.model.contacts.size());
  const double records = std::floor(r.run.t_end / r.run.dt / std::max(r.run.record_every, 1)) + 2.0;
  // Nine per-record vectors, each a 24-byte header and a heap block (about 24 bytes of overhead).
  const double per_record = nn * (5.0 * 24.0 + 72.0) + 9.0 * 48.0 +
                            nc * static_cast<double>(sizeof(rolling::ContactOutput)) +
                            static_cast<double>(sizeof(rolling::Energies)) + 8.0;
  const double write_copy = records * (nn * 72.0 + nc * 9.0 * 8.0);
  std::vector<std::string> elements;
  if (r.elements > 0) elements.push_back(key_text("beam", "elements", static_cast<double>(r.elements)));
  std::vector<std::string> history = {key_text("analysis", "dt", r.run.dt), key_text("analysis", "t_end", r.run.t_end),
                                      key_text("analysis", "record_every", static_cast<double>(r.run.record_every)),
                                      "[output] nodes (" + std::to_string(r.record.size()) + " recorded)"};
  for (const auto& e : elements) history.push_back(e);
  return {{records * per_record + write_copy, history,
           "time history, " + std::to_string(static_cast<long long>(records)) + " recorded states of " +
               std::to_string(static_cast<long long>(nn)) + " nodes"},
          {nodes * 6.0 * 8.0 * 400.0, elements,
           "beam model and its band Newton system, " + std::to_string(static_cast<long long>(nodes)) + " nodes"}};
}

}  // namespace

std::vector<MemoryItem> random_oscillator_memory(const study::KeyReader& s, int threads) {
  // Per thread: force, acceleration and the two uniform draws (3 n doubles); shared: the
  // synthesiser's FFT (measured: 0.91 GB peak at n = 1e7 on 2 threads).
  const auto signal = study::RecordSignalSection::parse(s);
  const double n = signal.sample_rate * signal.duration, t = threads;
  return {{8.0 * n * (3.0 * t + 5.0),
           {key_text("signal", "sample_rate", signal.sample_rate), key_text("signal", "duration", signal.duration)},
           "one realisation's record per thread"},
          chunk_sums(study::StudySection::parse(s), study::EnsembleSection::parse(s), study::SpectrumSection::parse(s),
                     1.0, {})};
}

std::vector<MemoryItem> texture_memory(const study::KeyReader& s, int /*threads*/) {
  const auto lines = study::LinesSection::parse(s);
  const double samples = lines.length / std::max(lines.spacing, 1e-300), count = static_cast<double>(lines.count);
  return {{8.0 * samples * (2.0 * count + 6.0),
           {key_text("lines", "count", count), key_text("lines", "length", lines.length),
            key_text("lines", "spacing", lines.spacing)},
           "line textures"},
          surfaces(study::SurfaceSection::parse(s))};
}

std::vector<MemoryItem> stiffness_memory(const study::KeyReader& s, int /*threads*/) {
  const auto f = study::SurfaceSection::parse(s);
  return {contact_grid(static_cast<double>(f.nx), static_cast<double>(f.ny))};
}

std::vector<MemoryItem> ball_on_beam_memory(const study::KeyReader& s, int threads) {
  return ball_on_beam(BallOnBeamSections::parse(s), threads);
}

std::vector<MemoryItem> rolling_pipe_memory(const study::KeyReader& s, int threads) {
  std::vector<Item> out;
  if (!study::PipeRoughnessSection::parse(s).line) {
    // One isotropic floor per realisation and thread, plus the generator's complex FFT grid.
    const auto f = study::SurfaceGridSection::parse(s);
    const double nx = static_cast<double>(f.nx), ny = static_cast<double>(f.ny);
    out.push_back({8.0 * nx * ny * (threads + 10.0),
                   {key_text("surface", "nx", nx), key_text("surface", "ny", ny)},
                   "rough floor per thread"});
  }
  const auto sensors = study::PipeSensorsSection::parse(s);
  out.push_back(chunk_sums(study::StudySection::parse(s), study::EnsembleSection::parse(s),
                           study::SpectrumSection::parse(s), static_cast<double>(sensors.positions.size()) + 2.0,
                           {positions_text("sensors", sensors.positions)}));
  return out;
}

std::vector<MemoryItem> rolling_beam_memory(const study::KeyReader& s, int /*threads*/) {
  return rolling_beam(read_rolling_beam_settings(s));
}

MemoryEstimate estimate_memory(const study::KeyReader& s, int threads) {
  MemoryEstimate e;
  e.bytes = kBaseline;
  double largest = -1.0;
  const auto& memory = find_scene(s.scene()).memory;
  for (const auto& it : memory ? memory(s, threads) : std::vector<MemoryItem>{}) {
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
