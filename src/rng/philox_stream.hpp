#pragma once
// Counter-based random streams (Random123 Philox4x64-10), keyed by (seed, index): a realisation's
// streams by (study seed, realisation id), a contact table's by (table seed, surface or strip index).
//
// Every random draw of a realisation comes from its own key, so a realisation's numbers never
// depend on thread count, rank count, scheduling or restarts. A realisation may open several
// independent streams (one per purpose: force phases, roughness phases, ...) by the stream tag,
// which occupies one word of the counter, the draw index the other.
#include <Random123/philox.h>
#include <Random123/u01fixedpt.h>

#include <cstddef>
#include <cstdint>

namespace rollspec::rng {

// Stream tags: one per purpose, so adding a new random input never shifts another's numbers.
enum class Stream : std::uint64_t {
  force_phase = 1,
  force_amplitude = 2,
  roughness_phase = 3,
  roughness_amplitude = 4,
  surface_phase = 5,
  surface_amplitude = 6,
  blocked_force_phase = 7,
  blocked_force_amplitude = 8,
  // The contact tables' surfaces and strips ([stiffness] table_seed): their own family, so a table
  // never shares numbers with the realisations it serves, whatever the two seeds.
  table_surface_phase = 9,
  table_surface_amplitude = 10,
  // compare's and fit's parametric bootstrap of the combined test's law (kernels/spectral D-31): keyed
  // by (kVerdictSeed, draw), so the same inputs give the same p-value.
  verdict_bootstrap = 11,
  // fit's replicate runs where common random numbers do not hold (kernels/spectral D-27i): replicate j of
  // a fit of study seed s runs with the seed drawn from (s, j), so every replicate's realisations are
  // independent of every other's and of the study seed's.
  fit_replicate_seed = 12,
};

inline constexpr std::uint64_t kVerdictSeed = 0x726f6c6c73706563ULL;  // "rollspec"

class PhiloxStream {
 public:
  PhiloxStream(std::uint64_t seed, std::uint64_t realisation, Stream stream)
      : key_{{seed, realisation}}, tag_(static_cast<std::uint64_t>(stream)) {}

  // Fills out[0..n) with doubles uniform on the open interval (0, 1) (never 0 or 1, so log(u)
  // and 1/u are safe), 4 per Philox block.
  void uniform_open(double* out, std::size_t n) const {
    using Philox = r123::Philox4x64;
    Philox gen;
    Philox::ctr_type ctr = {{0, 0, tag_, 0}};
    for (std::size_t i = 0; i < n; i += 4) {
      ctr[0] = i / 4;
      const Philox::ctr_type r = gen(ctr, key_);
      for (std::size_t k = 0; k < 4 && i + k < n; ++k) out[i + k] = u01fixedpt_open_open_64_double(r[k]);
    }
  }

 private:
  r123::Philox4x64::key_type key_;
  std::uint64_t tag_;
};

}  // namespace rollspec::rng
