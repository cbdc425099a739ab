#include "src/stiffness/blocked_force_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <omp.h>

#include "kernels/contact/hertz.hpp"
#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/psd.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::stiffness {

namespace {

constexpr std::size_t kMaxWindow = 128;      // cells: a 256^2 half-space product per CG iteration
constexpr std::size_t kMaxPositions = 1024;  // path positions of a derived strip
constexpr double kPeakSigmas = 7.0;          // the strip's highest point, in rms heights

// x rounded to three significant digits, up or down: readable cell sizes in the plan and the table.
double round3(double x, bool up) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2.0);
  const double q = x / unit;
  return (up ? std::ceil(q - 1e-9) : std::floor(q + 1e-9)) * unit;
}

// Rms height of the texture over the wavelengths a strip can hold (the longest derived strip,
// kMaxPositions steps of a / 3, down to a / 64, or the PSD's own cut-offs); 0 if the PSD cannot be
// integrated there. Waviness longer than the window still lifts its far side against the ball.
double strip_rms(const texture::Psd& psd, double a) {
  const double k_lo = std::max(psd.support_min, 2.0 * M_PI / (static_cast<double>(kMaxPositions) * a / 3.0));
  const double k_hi = std::min(psd.support_max, 128.0 * M_PI / a);
  if (!(k_hi > k_lo)) return 0.0;
  try {
    return std::sqrt(texture::integrate_psd(psd, k_lo, k_hi));
  } catch (const std::exception&) {
    return 0.0;
  }
}

}  // namespace

BlockedForceGeometry blocked_force_geometry(const study::BlockedForceSection& bf,
                                            const study::StripSurfaceSection& surface, const texture::Psd& psd,
                                            double radius, double e_star, double load, double max_step_length) {
  BlockedForceGeometry g;
  const double a = contact::hertz::contact_radius_at_load(radius, e_star, load);
  g.contact_radius = a;
  g.rms = strip_rms(psd, a);
  const double reach = std::max(1.5 * a, std::sqrt(2.0 * radius * (a * a / radius + kPeakSigmas * g.rms)));
  // Shortest texture wavelength along either axis after the anisotropy stretch.
  const double stretch = std::sqrt(surface.anisotropy);
  const double shortest = std::isfinite(psd.support_max) && psd.support_max > 0.0
                              ? 2.0 * M_PI / (psd.support_max * std::max(stretch, 1.0 / stretch))
                              : 0.0;
  const double want = shortest > 0.0 ? std::min(a / 8.0, shortest / 2.0) : a / 8.0;

  const bool window_set = bf.window > 0;
  g.derived_cell = !surface.spacing_set;
  if (!g.derived_cell) {
    g.cell = surface.spacing;
  } else {
    const double fit = 2.0 * reach / static_cast<double>(window_set ? bf.window : kMaxWindow);
    g.cell = want >= fit ? round3(want, false)
                         : (window_set ? round3(fit, true) : std::min(round3(fit, true), round3(a / 8.0, false)));
    if (shortest > 0.0 && 2.0 * g.cell > shortest * (1.0 + 1e-12)) g.truncated_wavelength = 2.0 * g.cell;
    if (shortest == 0.0) g.truncated_wavelength = 2.0 * g.cell;
  }
  const double dx = g.cell;
  g.window = window_set ? static_cast<std::size_t>(bf.window)
                        : texture::fast_even_length(static_cast<std::size_t>(std::ceil(2.0 * reach / dx - 1e-9)));
  g.ny = surface.ny_set ? static_cast<std::size_t>(surface.ny) : std::max<std::size_t>(g.window, 4);
  g.window = std::min(g.window, g.ny);

  double step_length = a / 3.0;
  if (max_step_length > 0.0) step_length = std::min(step_length, max_step_length);
  g.step = bf.step > 0 ? static_cast<std::size_t>(bf.step)
                       : std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(step_length / dx + 1e-9)));
  const double path_step = static_cast<double>(g.step) * dx;
  // At least four segments along the path: a roll-off longer than a quarter of the longest strip
  // leaves the lowest wavenumbers to the first bin (the F0 table holds it flat below).
  double correlation = 2.0 * M_PI * a;
  if (surface.self_affine) correlation = std::max(correlation, surface.rolloff_wavelength);
  g.segment = bf.segment > 0
                  ? static_cast<std::size_t>(bf.segment)
                  : texture::fast_even_length(std::min<std::size_t>(
                        kMaxPositions / 4,
                        std::max<std::size_t>(16, static_cast<std::size_t>(std::ceil(4.0 * correlation / path_step)))));
  if (bf.strip_length > 0.0) {
    g.nx = static_cast<std::size_t>(std::round(bf.strip_length / dx));
  } else {
    const std::size_t wanted = std::min(4 * g.segment, kMaxPositions);
    g.nx = g.window + wanted * g.step;
  }
  g.nx += g.nx % 2;
  // Refused here, so that `plan` refuses what `run` would.
  if (g.window < 8)
    (window_set ? bf.origin(bf.window) : surface.ny_origin)
        .refuse("leaves a solver window of " + std::to_string(g.window) + " cells; allowed: 8 or more");
  if (g.segment < 16) bf.origin(bf.segment).refuse("is shorter than 16 positions; allowed: 0 (derived) or 16 or more");
  if (g.nx < g.window + 16 * g.step)
    bf.origin(bf.strip_length).refuse("leaves fewer than 16 path positions outside the window");
  for (std::size_t j = g.window / 2; j + g.window / 2 < g.nx; j += g.step) ++g.positions;

  // Cost: c = 2.9e-7 s per position of the whole load search (contact_box_work), plus the solvers'
  // set-up (FFT plans of the window's boxes and the coarse grid, made on the first cold solves): about
  // 0.5 s on a 128-cell window (the Ra 0.3 um finish's derived strip: the pre-search's first path of 34
  // positions 0.67 s, its second 0.14 s), which short strips otherwise miss (bench_plan_estimates.py).
  constexpr double kSetupSeconds = 0.5;
  // contact BF-9 (answer_tolerance > 0): one loose path and its checks, 0.25 of the search's CPU beyond the
  // set-up (fitted on the rig and smooth textures of bench_plan_estimates.py: 0.24, 0.26), up to the whole
  // search's where the checks refine to every position (0.93 on its rough texture).
  const double search = 2.9e-7 * contact_box_work(g, g.window, radius) * static_cast<double>(g.positions);
  g.estimated_seconds = kSetupSeconds + (bf.answer_tolerance > 0.0 ? 0.25 : 1.0) * search;
  g.refined_seconds = bf.answer_tolerance > 0.0 ? kSetupSeconds + search : 0.0;
  g.threads = std::max(1, std::min(omp_get_max_threads(), static_cast<int>((g.positions + 63) / 64)));
  return g;
}

// A CG iteration works on the box of the contact (Eq. 3c), about the Hertz diameter 2a, padded to
// twice its side: m log2 m with m = (2 min(2a/dx, window))^2. Rough textures (sigma against delta_H =
// a^2/R) touch on fewer cells and converge in fewer iterations: a factor 1 / (1 + sigma/delta_H).
// Fitted (kernel version 7, one thread, whole builds less the cached run, bench_plan_estimates.py) on
// the seed 002 rig (a/24, sigma/delta_H 0.37), the Ra 0.3 um surface (a/13, 1.57) and a smoother one
// (a/29, 0.21), each the geometric mean of two sessions' builds (which differed by up to 27 %): the
// blocked-force load search at c = 2.9e-7 s, the value that centres their estimate/measured ratios;
// the path table at 3.7e-7 s per solve on the same three (36, 4.3, 53 ms), within 1.2.
double contact_box_work(const BlockedForceGeometry& g, std::size_t window, double radius) {
  const double box = std::min(2.0 * g.contact_radius / g.cell, static_cast<double>(window));
  const double m = 4.0 * box * box, delta_h = g.contact_radius * g.contact_radius / radius;
  return m * std::log2(m) / (1.0 + g.rms / delta_h);
}

std::string BlockedForceGeometry::describe() const {
  std::string buf;
  const double dx = cell;
  buf = io::formatted(
      "cell %s (a/%.3g)%s, window %zu cells (%s), strip %zu x %zu cells (%s wide, %s long), step %zu cells "
      "(%s), %zu positions, Welch segment %zu; contact radius a = %s, texture rms %s; build about %.2g s CPU, "
      "%.2g s wall on %d thread%s",
      um(dx).c_str(), contact_radius / dx,
      truncated_wavelength > 0.0 ? (", texture below " + um(truncated_wavelength) + " dropped").c_str() : "", window,
      um(static_cast<double>(window) * dx).c_str(), ny, nx, um(static_cast<double>(ny) * dx).c_str(),
      um(static_cast<double>(nx) * dx).c_str(), step, um(static_cast<double>(step) * dx).c_str(), positions, segment,
      um(contact_radius).c_str(), um(rms).c_str(), estimated_seconds, estimated_seconds / threads, threads,
      threads == 1 ? "" : "s");
  if (refined_seconds > 0.0)
    buf += io::formatted(" (up to %.2g s CPU where its checks refine to every position)", refined_seconds);
  return buf;
}

}  // namespace rollspec::stiffness
