#pragma once
// The grid of the blocked-force stage: cell size, strip width and length, solver window, path step
// and Welch segment. Each comes from the study when it sets the key, and is otherwise derived from
// the Hertz contact radius under the ball's weight and the texture:
//
//   a = (3 W R / (4 E*))^(1/3),  delta_H = a^2 / R,  sigma = rms height of the texture.
//   Window: every strip cell outside it must stay clear of the ball at the approach the load
//     search can reach (the kernel refuses the path otherwise). The approach from the mean plane
//     stays below the smooth delta_H (asperities carry the ball higher), and the strip's highest
//     point lies within about 5 sigma, so the window holds the disc of radius
//     L = max(1.5 a, sqrt(2 R (delta_H + 5 sigma))).
//   Cell: a / 8 (the patch resolved) and half the texture's shortest wavelength (no roughness
//     truncated) when the window then stays within 128 cells; otherwise the cell that puts 2 L in
//     128 cells (never coarser than a / 8), with the roughness shorter than two cells dropped.
//   Strip width: the window.  Step: a / 3 (the F0 PSD along the path is some 45 dB down at the
//     path's Nyquist wavelength 2 a / 3), and at most v / f_s so the path resolves every frequency
//     of the output.  Segment: 8 pi a (four times the patch's correlation length 2 pi a, or the
//     self-affine roll-off wavelength if longer).  Strip length: four segments of positions (seven
//     half-overlapping Welch segments), at most 1024 positions, plus the window.
#include <cstddef>
#include <string>

#include "kernels/texture/psd.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/strip_surface_section.hpp"

namespace rollspec::stiffness {

struct BlockedForceGeometry {
  double contact_radius = 0.0;        // Hertz a at the load (m)
  double rms = 0.0;                   // texture rms height used for the window (m)
  double cell = 0.0;                  // strip and window cell dx = dy (m)
  std::size_t ny = 0;                 // strip width (cells)
  std::size_t nx = 0;                 // strip length (cells, even)
  std::size_t window = 0;             // solver window (cells, square, at most ny)
  std::size_t step = 0;               // path step (cells)
  std::size_t segment = 0;            // Welch segment of the F0 PSD (positions; the build clips it to the path)
  std::size_t positions = 0;          // ball positions along the path
  bool derived_cell = false;          // [surface] spacing not set: roughness beyond the grid may be truncated
  double truncated_wavelength = 0.0;  // > 0: texture wavelengths below it are dropped (m)
  double estimated_seconds = 0.0;     // CPU seconds of the table build, this engine's solver speed (rough)
  double refined_seconds = 0.0;       // contact BF-9: the build's CPU seconds if its checks refine to every position
  int threads = 1;                    // threads the build uses (OMP_NUM_THREADS, at most one per chunk)

  // "cell 4.6 um (a/15), window 128 cells (589 um), ..." for the plan and the run's log.
  std::string describe() const;
};

// `psd`: the study's [texture] PSD; `max_step_length`: the longest path step the dynamics can use
// (v / f_s), 0 for no limit.
BlockedForceGeometry blocked_force_geometry(const study::BlockedForceSection& blocked_force,
                                            const study::StripSurfaceSection& surface, const texture::Psd& psd,
                                            double radius, double effective_modulus, double load,
                                            double max_step_length);

// The relative cost of one contact solve on g's grid in a window of `window` cells (ball radius
// `radius`): plan's table estimates scale it by a measured constant per table kind.
double contact_box_work(const BlockedForceGeometry& g, std::size_t window, double radius);

}  // namespace rollspec::stiffness
