// Test support: Philox4x64 draws keyed by (seed, 0), written once for the spectral kernels' Monte-Carlo tests.
#pragma once

#include <Random123/philox.h>
#include <Random123/u01fixedpt.h>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace rollspec::spectral::testing {

// Uniforms on (0, 1), four per Philox block, blocks counted from 0.
class PhiloxUniforms {
 public:
  explicit PhiloxUniforms(std::uint64_t seed) : key_{{seed, 0}} {}
  double next() {
    if (used_ == 4) {
      block_ = gen_({{counter_++, 0, 0, 0}}, key_);
      used_ = 0;
    }
    return u01fixedpt_open_open_64_double(block_[used_++]);
  }

 private:
  r123::Philox4x64 gen_;
  r123::Philox4x64::key_type key_;
  r123::Philox4x64::ctr_type block_{};
  std::uint64_t counter_ = 0;
  int used_ = 4;
};

// Standard normals: Box-Muller on successive pairs of uniforms, both used.
class PhiloxNormals {
 public:
  explicit PhiloxNormals(std::uint64_t seed) : uniform_(seed) {}
  double next() {
    if (have_second_) {
      have_second_ = false;
      return second_;
    }
    const double r = std::sqrt(-2.0 * std::log(uniform_.next())), phi = 2.0 * M_PI * uniform_.next();
    second_ = r * std::sin(phi);
    have_second_ = true;
    return r * std::cos(phi);
  }

 private:
  PhiloxUniforms uniform_;
  double second_ = 0.0;
  bool have_second_ = false;
};

// A bootstrap's uniforms keyed by (seed, draw), counter i / 4 within the draw: the counter-based stream family the
// engine hands kernels/spectral's band_test_with_table (one key per draw, so any order of draws gives the same bits).
inline void draw_uniforms(std::uint64_t seed, std::uint64_t draw, double* u, std::size_t n) {
  r123::Philox4x64 gen;
  const r123::Philox4x64::key_type key = {{seed, draw}};
  for (std::size_t i = 0; i < n; i += 4) {
    const r123::Philox4x64::ctr_type ctr = {{i / 4, 0, 0, 0}};
    const auto r = gen(ctr, key);
    for (std::size_t k = 0; k < 4 && i + k < n; ++k) u[i + k] = u01fixedpt_open_open_64_double(r[k]);
  }
}

}  // namespace rollspec::spectral::testing
