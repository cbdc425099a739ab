// D-24 and D-25 (kernels/spectral/tabulated_math.hpp) against long-double libm: -ln u within 2 ulp
// of the value, cos and sin of 2 pi v within 1 ulp of 1, over random arguments and the edges
// (u near 0 and 1, bin and quadrant boundaries).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "kernels/spectral/tabulated_math.hpp"
#include "kernels/spectral/tabulated_math_avx512.hpp"

using rollspec::spectral::neg_log_open;
using rollspec::spectral::sincos_two_pi;
using rollspec::spectral::tabulated_math;

namespace {
// Arguments: 53-bit uniforms on (0, 1) as the engine's Philox doubles, u^8 (small u), 1 - tiny,
// and the neighbours of every log bin edge 1 + i/256 (scaled into [1/2, 1)) and phase step k/1024.
std::vector<double> arguments() {
  std::vector<double> v;
  std::mt19937_64 g(18);
  for (int i = 0; i < 400000; ++i) {
    const double u = (static_cast<double>(g() >> 11) + 0.5) * 0x1p-53;
    v.push_back(u);
    v.push_back(u * u * u * u * u * u * u * u);
  }
  for (double d = 0x1p-53; d < 0.01; d *= 1.7) v.push_back(1.0 - d);
  for (int i = 1; i < 256; ++i) {
    const double e = 0.5 + i / 512.0;
    v.push_back(e);
    v.push_back(std::nextafter(e, 0.0));
    v.push_back(std::nextafter(e, 1.0));
  }
  for (int k = 1; k < 1024; ++k) {
    const double e = k / 1024.0, m = (k - 0.5) / 1024.0;
    for (double x : {e, m}) {
      v.push_back(x);
      v.push_back(std::nextafter(x, 0.0));
      v.push_back(std::nextafter(x, 1.0));
    }
  }
  v.push_back(0x1p-54);
  v.push_back(std::nextafter(1.0, 0.0));
  return v;
}

double ulp_of(double x) { return std::ldexp(1.0, std::ilogb(x) - 52); }

#if defined(ROLLSPEC_HAVE_AVX2_PATH)
// The four-lane forms on four arguments (phase v, amplitude u) into c, s, -ln u.
__attribute__((target("avx2"))) void four_lanes(const double* v, const double* u, double* c, double* s, double* l) {
  const auto& t = tabulated_math();
  __m256d vc, vs;
  sincos_two_pi(_mm256_loadu_pd(v), t, vc, vs);
  _mm256_storeu_pd(c, vc);
  _mm256_storeu_pd(s, vs);
  _mm256_storeu_pd(l, neg_log_open(_mm256_loadu_pd(u), t));
}
#endif

// Lanes of the W-lane forms `lanes(v, u, c, s, l)` (phases v, amplitudes u into c, s, -ln u) over v in steps of W,
// the amplitudes v itself where it lies in (0, 1), else 1/2, that differ from the scalar forms' bits.
template <std::size_t W, class Lanes>
std::size_t lane_mismatches(const std::vector<double>& v, Lanes&& lanes) {
  const auto& t = tabulated_math();
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i + W - 1 < v.size(); i += W) {
    double c[W], s[W], l[W], ul[W];
    for (std::size_t k = 0; k < W; ++k) ul[k] = v[i + k] > 0.0 && v[i + k] < 1.0 ? v[i + k] : 0.5;
    lanes(&v[i], ul, c, s, l);
    for (std::size_t k = 0; k < W; ++k) {
      double cs, ss;
      sincos_two_pi(v[i + k], t, cs, ss);
      mismatches += (c[k] != cs) + (s[k] != ss) + (l[k] != neg_log_open(ul[k], t));
    }
  }
  return mismatches;
}
}  // namespace

TEST_CASE("D-24: -ln u from the table is within 2 ulp of long-double libm on (0, 1)") {
  const auto& t = tabulated_math();
  double worst = 0.0;
  for (double u : arguments()) {
    const long double exact = -std::log(static_cast<long double>(u));
    const double got = neg_log_open(u, t);
    worst =
        std::max(worst, static_cast<double>(std::fabs(static_cast<long double>(got) - exact)) / ulp_of(double(exact)));
  }
  MESSAGE("worst -ln u error: " << worst << " ulp");
  CHECK(worst <= 2.0);
}

TEST_CASE("D-25: cos and sin of 2 pi v from the table are within 1 ulp of 1 of long-double libm") {
  const auto& t = tabulated_math();
  const long double two_pi = 6.283185307179586476925286766559005768L;
  double worst_c = 0.0, worst_s = 0.0, worst_norm = 0.0;
  std::vector<double> v = arguments();
  v.push_back(0.0);
  v.push_back(1.0);
  for (double x : v) {
    double c, s;
    sincos_two_pi(x, t, c, s);
    const long double a = two_pi * static_cast<long double>(x);
    worst_c = std::max(worst_c, static_cast<double>(std::fabs(c - std::cos(a))) / 0x1p-52);
    worst_s = std::max(worst_s, static_cast<double>(std::fabs(s - std::sin(a))) / 0x1p-52);
    worst_norm = std::max(worst_norm, std::fabs(c * c + s * s - 1.0));
  }
  MESSAGE("worst cos / sin error: " << worst_c << " / " << worst_s << " ulp of 1");
  CHECK(worst_c <= 1.0);
  CHECK(worst_s <= 1.0);
  CHECK(worst_norm <= 4.0 * std::numeric_limits<double>::epsilon());
#if defined(ROLLSPEC_HAVE_SSE2_PATH)
  // The two-lane forms the synthesis loop uses give each lane the scalar form's bits.
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) {
    double c[2], s[2], l[2];
    __m128d vc, vs;
    sincos_two_pi(_mm_loadu_pd(&v[i]), t, vc, vs);
    _mm_storeu_pd(c, vc);
    _mm_storeu_pd(s, vs);
    const double ul[2] = {v[i] > 0.0 && v[i] < 1.0 ? v[i] : 0.5, v[i + 1] > 0.0 && v[i + 1] < 1.0 ? v[i + 1] : 0.5};
    _mm_storeu_pd(l, neg_log_open(_mm_loadu_pd(ul), t));
    for (int k = 0; k < 2; ++k) {
      double cs, ss;
      sincos_two_pi(v[i + static_cast<std::size_t>(k)], t, cs, ss);
      CHECK(c[k] == cs);
      CHECK(s[k] == ss);
      CHECK(l[k] == neg_log_open(ul[k], t));
    }
  }
#endif
#if defined(ROLLSPEC_HAVE_AVX2_PATH)
  if (__builtin_cpu_supports("avx2")) {
    CHECK(lane_mismatches<4>(v, four_lanes) == 0);
  } else {
    MESSAGE("no AVX2 on this CPU: four-lane forms not checked");
  }
#endif
  // The eight-lane forms (AVX-512F) too; their source is compiled without contraction into FMA.
  if (rollspec::spectral::cpu_has_avx512f()) {
    CHECK(lane_mismatches<8>(v, [&](const double* x, const double* u, double* c, double* s, double* l) {
            rollspec::spectral::sincos_two_pi_x8(x, t, c, s);
            rollspec::spectral::neg_log_open_x8(u, t, l);
          }) == 0);
  } else {
    MESSAGE("no AVX-512F on this CPU: eight-lane forms not checked");
  }
  // Quarter turns are exact.
  for (int q = 0; q < 4; ++q) {
    double c, s;
    sincos_two_pi(q / 4.0, t, c, s);
    const double ce[4] = {1, 0, -1, 0}, se[4] = {0, 1, 0, -1};
    CHECK(c == ce[q]);
    CHECK(s == se[q]);
  }
}
