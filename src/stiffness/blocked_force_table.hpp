#pragma once
// Blocked-force tables for the linearised contact law (seed 002 §4.2; design D-11; kernels/contact
// blocked_force.hpp BF-1..BF-7): a smooth ball slid along one rough strip realisation at the fixed
// approach d0 whose mean force is the ball's weight. The table holds F0 and k along the path, d0,
// k0 = mean k, and the one-sided PSD of F0 along the path (per rad/m), from which the ball-on-beam
// scene synthesises F0(t) realisations at any speed (D-2: G_t(f) = 2 pi G_k(2 pi f / v) / v).
// Cached and checked like stiffness tables (input hash, schema, kernel version, data checksum).
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"

namespace rollspec::study {
class Study;
}

namespace rollspec::stiffness {

constexpr const char* kBlockedForceFileType = "rollspec-blocked-force";

struct BlockedForceTable {
  std::vector<double> position, force, stiffness;  // m, N, N/m along the path
  std::vector<double> psd_wavenumber, psd;          // rad/m, N^2 m / rad (one-sided PSD of F0 - mean)
  double approach = 0.0, k0 = 0.0, mean_force = 0.0, load = 0.0;
  std::string inputs, input_hash;
  // G of F0 at wavenumber k: log-log between the PSD bins, the first bin's level below them, zero
  // above the path's Nyquist wavenumber.
  double psd_at(double k) const;
};

std::vector<study::KeySpec> blocked_force_keys();

BlockedForceTable resolve_blocked_force(const study::Study& s, double radius, double effective_modulus, double load,
                                        bool rebuild, bool quiet, std::string& status);

}  // namespace rollspec::stiffness
