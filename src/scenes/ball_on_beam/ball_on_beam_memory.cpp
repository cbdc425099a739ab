// Scene `ball-on-beam`'s memory model (its registry row's `memory`, memory_estimate.hpp): time records,
// the ensemble's sums, the table-error sub-scenes, stored histories and what its contact law solves.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "src/io/number_text.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"
#include "src/scenes/memory_terms.hpp"
#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "kernels/contact/path_table.hpp"
#include "src/stiffness/path_table.hpp"

namespace rollspec::scenes {

namespace {

using Item = MemoryItem;

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
  // B43b holds room for every position's ladder to grow to max_approaches rows.
  const double rows =
      static_cast<double>(g.ladder ? std::max(g.approaches, contact::PathTableOptions{}.max_approaches) : g.approaches);
  const double cells = rows * static_cast<double>(g.positions);
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

}  // namespace

std::vector<MemoryItem> ball_on_beam_memory(const study::KeyReader& s, int threads) {
  return ball_on_beam(BallOnBeamSections::parse(s), threads);
}

}  // namespace rollspec::scenes
