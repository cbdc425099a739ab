#pragma once
// The two transcendental maps of spectral synthesis (D-3) without a libm call: the Rayleigh factor
// sqrt(-ln u) needs -ln u, the phase 2 pi v needs cos and sin. Each is a table of exact values at
// 2^-8 (log) or 2^-10 (phase) steps, computed once, and a short polynomial for the remainder
// (kernels/spectral/README.md D-24, D-25). Plain +, -, *, / and one table load each: no branch, no
// fused multiply-add (the build targets baseline x86-64, and the AVX2 forms do not enable FMA), so
// the scalar, SSE2 and AVX2 forms, and the AVX-512F ones (tabulated_math_avx512.hpp; fused only
// where a product is exact, which rounds the same), give the same bits on every machine. Accuracy, checked against
// long-double libm in the tests: -ln u within 2 ulp of the value, cos and sin within 1 ulp of 1.
#include <cstddef>
#include <cstdint>
#include <cstring>
// ROLLSPEC_HAVE_SSE2_PATH: two-lane forms (x86-64 always has SSE2); ROLLSPEC_HAVE_AVX2_PATH:
// four-lane forms, used only where the CPU reports AVX2 at run time.
#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#define ROLLSPEC_HAVE_SSE2_PATH 1
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define ROLLSPEC_HAVE_AVX2_PATH 1
#endif

namespace rollspec::spectral {

struct TabulatedMath {
  // ln, per mantissa bin i: the centre c_i = 1 + (i + 1/2) / 256 (the last one: 2), 1 / c_i and
  // ln(c_i / 2), side by side (one cache line per two bins).
  struct alignas(32) LogBin {
    double centre, inverse, half_centre, unused;
  };
  LogBin log_bin[256];
  // cos and sin of 2 pi k / 1024, k = 0..1023, interleaved.
  alignas(16) double cos_sin[2048];
};

const TabulatedMath& tabulated_math();  // built on first use (thread-safe), never changes

namespace tabulated_detail {
// ln 2 split so that (e + 1) ln2_hi is exact for |e + 1| < 2^11 (Cody-Waite).
constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
constexpr double phase_step = 2.0 * 3.14159265358979323846 / 1024.0;  // 2 pi / 1024
// ln(1 + r) = r - r^2/2 + ... + r^7/7, Horner.
inline double log1p_series(double r) {
  return r * (1.0 - r * (0.5 - r * (1.0 / 3.0 - r * (0.25 - r * (0.2 - r * (1.0 / 6.0 - r * (1.0 / 7.0)))))));
}
inline double cos_series(double t2) { return 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0 - t2 * (1.0 / 720.0))); }
inline double sin_series(double t, double t2) {
  return t - t * t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0 - t2 * (1.0 / 5040.0)));
}
}  // namespace tabulated_detail

// -ln u for u in (0, 1) (a positive normal double; D-24):
//   u = 2^e m, m in [1, 2); c the centre of m's 2^-8 bin (the top bin's: 2); r = (m - c) / c, |r| <= 2^-9:
//   -ln u = -[(e + 1) ln 2 + ln(c / 2) + ln(1 + r)],  ln(1 + r) by its Taylor series to r^7 (|err| < r^8/8).
inline double neg_log_open(double u, const TabulatedMath& t) {
  std::uint64_t bits;
  std::memcpy(&bits, &u, sizeof bits);
  const auto e1 = static_cast<double>(static_cast<std::int32_t>(bits >> 52) - 1022);  // e + 1
  const auto i = static_cast<std::size_t>((bits >> 44) & 255u);
  const std::uint64_t mbits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
  double m;
  std::memcpy(&m, &mbits, sizeof m);
  const TabulatedMath::LogBin& b = t.log_bin[i];
  const double r = (m - b.centre) * b.inverse;  // m - c exact (Sterbenz)
  const double p = tabulated_detail::log1p_series(r);
  using tabulated_detail::ln2_hi, tabulated_detail::ln2_lo;
  return -((e1 * ln2_hi + b.half_centre) + (e1 * ln2_lo + p));
}

// cos(2 pi v) and sin(2 pi v) for v in [0, 1] (D-25):
//   v = k / 1024 + s / 1024, k = round(1024 v), |s| <= 1/2, t = 2 pi s / 1024 (|t| <= pi / 1024):
//   cos = C_k cos t - S_k sin t, sin = S_k cos t + C_k sin t, cos t and sin t by Taylor to t^6 / t^7.
inline void sincos_two_pi(double v, const TabulatedMath& tab, double& c, double& s) {
  const double x = v * 1024.0;                                                   // exact
  const auto k = static_cast<std::int32_t>(x + 0.5);                             // round half up, x >= 0
  const double t = (x - static_cast<double>(k)) * tabulated_detail::phase_step;  // x - k exact
  const double t2 = t * t;
  const double ct = tabulated_detail::cos_series(t2), st = tabulated_detail::sin_series(t, t2);
  const double* cs = tab.cos_sin + 2 * static_cast<std::size_t>(k & 1023);
  c = cs[0] * ct - cs[1] * st;
  s = cs[1] * ct + cs[0] * st;
}

#if defined(ROLLSPEC_HAVE_SSE2_PATH)
// Two lanes at once: the same operations in the same order as the scalar forms above (IEEE
// double +, -, *, exact conversions), so each lane's bits equal the scalar result.
namespace tabulated_detail {
inline __m128d horner_log1p(__m128d r) {
  const auto c = [](double x) { return _mm_set1_pd(x); };
  __m128d p = _mm_sub_pd(c(1.0 / 6.0), _mm_mul_pd(r, c(1.0 / 7.0)));
  p = _mm_sub_pd(c(0.2), _mm_mul_pd(r, p));
  p = _mm_sub_pd(c(0.25), _mm_mul_pd(r, p));
  p = _mm_sub_pd(c(1.0 / 3.0), _mm_mul_pd(r, p));
  p = _mm_sub_pd(c(0.5), _mm_mul_pd(r, p));
  p = _mm_sub_pd(c(1.0), _mm_mul_pd(r, p));
  return _mm_mul_pd(r, p);
}
}  // namespace tabulated_detail

inline __m128d neg_log_open(__m128d u, const TabulatedMath& t) {
  using namespace tabulated_detail;
  const __m128i bits = _mm_castpd_si128(u);
  // e + 1 = (bits >> 52) - 1022, converted exactly through the 2^52 trick.
  const __m128i two52 = _mm_set1_epi64x(0x4330000000000000LL);
  const __m128d ex = _mm_sub_pd(_mm_castsi128_pd(_mm_or_si128(_mm_srli_epi64(bits, 52), two52)), _mm_set1_pd(0x1p52));
  const __m128d e1 = _mm_sub_pd(ex, _mm_set1_pd(1022.0));
  const __m128i idx = _mm_and_si128(_mm_srli_epi64(bits, 44), _mm_set1_epi64x(255));
  const auto i0 = static_cast<std::size_t>(_mm_cvtsi128_si64(idx));
  const auto i1 = static_cast<std::size_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(idx, idx)));
  const __m128d m = _mm_castsi128_pd(
      _mm_or_si128(_mm_and_si128(bits, _mm_set1_epi64x(0x000fffffffffffffLL)), _mm_set1_epi64x(0x3ff0000000000000LL)));
  const __m128d b0 = _mm_load_pd(&t.log_bin[i0].centre), b1 = _mm_load_pd(&t.log_bin[i1].centre);
  const __m128d centre = _mm_unpacklo_pd(b0, b1), inverse = _mm_unpackhi_pd(b0, b1);
  const __m128d half_centre = _mm_loadh_pd(_mm_load_sd(&t.log_bin[i0].half_centre), &t.log_bin[i1].half_centre);
  const __m128d r = _mm_mul_pd(_mm_sub_pd(m, centre), inverse);
  const __m128d p = horner_log1p(r);
  const __m128d sum = _mm_add_pd(_mm_add_pd(_mm_mul_pd(e1, _mm_set1_pd(ln2_hi)), half_centre),
                                 _mm_add_pd(_mm_mul_pd(e1, _mm_set1_pd(ln2_lo)), p));
  return _mm_xor_pd(sum, _mm_set1_pd(-0.0));
}

inline void sincos_two_pi(__m128d v, const TabulatedMath& tab, __m128d& c, __m128d& s) {
  using namespace tabulated_detail;
  const auto k1 = [](double x) { return _mm_set1_pd(x); };
  const __m128d x = _mm_mul_pd(v, k1(1024.0));
  const __m128i k = _mm_cvttpd_epi32(_mm_add_pd(x, k1(0.5)));
  const __m128d t = _mm_mul_pd(_mm_sub_pd(x, _mm_cvtepi32_pd(k)), k1(phase_step));
  const __m128d t2 = _mm_mul_pd(t, t);
  __m128d ct = _mm_sub_pd(k1(1.0 / 24.0), _mm_mul_pd(t2, k1(1.0 / 720.0)));
  ct = _mm_sub_pd(k1(0.5), _mm_mul_pd(t2, ct));
  ct = _mm_sub_pd(k1(1.0), _mm_mul_pd(t2, ct));
  __m128d st = _mm_sub_pd(k1(1.0 / 120.0), _mm_mul_pd(t2, k1(1.0 / 5040.0)));
  st = _mm_sub_pd(k1(1.0 / 6.0), _mm_mul_pd(t2, st));
  st = _mm_sub_pd(t, _mm_mul_pd(_mm_mul_pd(t, t2), st));
  const auto j0 = static_cast<std::size_t>(_mm_cvtsi128_si32(k) & 1023);
  const auto j1 = static_cast<std::size_t>(_mm_cvtsi128_si32(_mm_srli_si128(k, 4)) & 1023);
  const __m128d p0 = _mm_load_pd(tab.cos_sin + 2 * j0), p1 = _mm_load_pd(tab.cos_sin + 2 * j1);
  const __m128d cc = _mm_unpacklo_pd(p0, p1), ss = _mm_unpackhi_pd(p0, p1);
  c = _mm_sub_pd(_mm_mul_pd(cc, ct), _mm_mul_pd(ss, st));
  s = _mm_add_pd(_mm_mul_pd(ss, ct), _mm_mul_pd(cc, st));
}
#endif

#if defined(ROLLSPEC_HAVE_AVX2_PATH)
// Four lanes, for CPUs with AVX2 (chosen at run time; the build itself targets baseline x86-64).
// AVX2 without FMA: again the scalar form's operations in its order, so the same bits.
__attribute__((target("avx2"))) inline __m256d neg_log_open(__m256d u, const TabulatedMath& t) {
  using namespace tabulated_detail;
  const __m256i bits = _mm256_castpd_si256(u);
  const __m256i two52 = _mm256_set1_epi64x(0x4330000000000000LL);
  const __m256d ex =
      _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(_mm256_srli_epi64(bits, 52), two52)), _mm256_set1_pd(0x1p52));
  const __m256d e1 = _mm256_sub_pd(ex, _mm256_set1_pd(1022.0));
  // Each lane's bin (32 bytes: centre, inverse, half_centre, unused) by one load, then a 4 x 4
  // transpose (plain loads: gathers are slow on CPUs with the gather-data-sampling fix).
  const __m256i idx = _mm256_and_si256(_mm256_srli_epi64(bits, 44), _mm256_set1_epi64x(255));
  const __m128i lo = _mm256_castsi256_si128(idx), hi = _mm256_extracti128_si256(idx, 1);
  const __m256d b0 = _mm256_load_pd(&t.log_bin[static_cast<std::size_t>(_mm_cvtsi128_si64(lo))].centre);
  const __m256d b1 = _mm256_load_pd(&t.log_bin[static_cast<std::size_t>(_mm_extract_epi64(lo, 1))].centre);
  const __m256d b2 = _mm256_load_pd(&t.log_bin[static_cast<std::size_t>(_mm_cvtsi128_si64(hi))].centre);
  const __m256d b3 = _mm256_load_pd(&t.log_bin[static_cast<std::size_t>(_mm_extract_epi64(hi, 1))].centre);
  const __m256d t0 = _mm256_unpacklo_pd(b0, b1), t1 = _mm256_unpackhi_pd(b0, b1);  // (c0 c1 h0 h1), (i0 i1 . .)
  const __m256d t2 = _mm256_unpacklo_pd(b2, b3), t3 = _mm256_unpackhi_pd(b2, b3);
  const __m256d centre = _mm256_permute2f128_pd(t0, t2, 0x20), half_centre = _mm256_permute2f128_pd(t0, t2, 0x31);
  const __m256d inverse = _mm256_permute2f128_pd(t1, t3, 0x20);
  const __m256d m = _mm256_castsi256_pd(_mm256_or_si256(
      _mm256_and_si256(bits, _mm256_set1_epi64x(0x000fffffffffffffLL)), _mm256_set1_epi64x(0x3ff0000000000000LL)));
  const __m256d r = _mm256_mul_pd(_mm256_sub_pd(m, centre), inverse);
  __m256d p = _mm256_sub_pd(_mm256_set1_pd(1.0 / 6.0), _mm256_mul_pd(r, _mm256_set1_pd(1.0 / 7.0)));
  p = _mm256_sub_pd(_mm256_set1_pd(0.2), _mm256_mul_pd(r, p));
  p = _mm256_sub_pd(_mm256_set1_pd(0.25), _mm256_mul_pd(r, p));
  p = _mm256_sub_pd(_mm256_set1_pd(1.0 / 3.0), _mm256_mul_pd(r, p));
  p = _mm256_sub_pd(_mm256_set1_pd(0.5), _mm256_mul_pd(r, p));
  p = _mm256_sub_pd(_mm256_set1_pd(1.0), _mm256_mul_pd(r, p));
  p = _mm256_mul_pd(r, p);
  const __m256d sum = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(e1, _mm256_set1_pd(ln2_hi)), half_centre),
                                    _mm256_add_pd(_mm256_mul_pd(e1, _mm256_set1_pd(ln2_lo)), p));
  return _mm256_xor_pd(sum, _mm256_set1_pd(-0.0));
}

__attribute__((target("avx2"))) inline void sincos_two_pi(__m256d v, const TabulatedMath& tab, __m256d& c, __m256d& s) {
  using namespace tabulated_detail;
  const __m256d x = _mm256_mul_pd(v, _mm256_set1_pd(1024.0));
  const __m128i k = _mm256_cvttpd_epi32(_mm256_add_pd(x, _mm256_set1_pd(0.5)));
  const __m256d t = _mm256_mul_pd(_mm256_sub_pd(x, _mm256_cvtepi32_pd(k)), _mm256_set1_pd(phase_step));
  const __m256d t2 = _mm256_mul_pd(t, t);
  __m256d ct = _mm256_sub_pd(_mm256_set1_pd(1.0 / 24.0), _mm256_mul_pd(t2, _mm256_set1_pd(1.0 / 720.0)));
  ct = _mm256_sub_pd(_mm256_set1_pd(0.5), _mm256_mul_pd(t2, ct));
  ct = _mm256_sub_pd(_mm256_set1_pd(1.0), _mm256_mul_pd(t2, ct));
  __m256d st = _mm256_sub_pd(_mm256_set1_pd(1.0 / 120.0), _mm256_mul_pd(t2, _mm256_set1_pd(1.0 / 5040.0)));
  st = _mm256_sub_pd(_mm256_set1_pd(1.0 / 6.0), _mm256_mul_pd(t2, st));
  st = _mm256_sub_pd(t, _mm256_mul_pd(_mm256_mul_pd(t, t2), st));
  // (C, S) of each lane by one 16-byte load; x = lanes 0 and 2, y = lanes 1 and 3.
  const __m128i at = _mm_and_si128(k, _mm_set1_epi32(1023));
  const double* cs = tab.cos_sin;
  const __m128d p0 = _mm_load_pd(cs + 2 * _mm_cvtsi128_si32(at)), p1 = _mm_load_pd(cs + 2 * _mm_extract_epi32(at, 1));
  const __m128d p2 = _mm_load_pd(cs + 2 * _mm_extract_epi32(at, 2)),
                p3 = _mm_load_pd(cs + 2 * _mm_extract_epi32(at, 3));
  const __m256d x02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(p0), p2, 1);
  const __m256d x13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(p1), p3, 1);
  const __m256d cc = _mm256_unpacklo_pd(x02, x13), ss = _mm256_unpackhi_pd(x02, x13);
  c = _mm256_sub_pd(_mm256_mul_pd(cc, ct), _mm256_mul_pd(ss, st));
  s = _mm256_add_pd(_mm256_mul_pd(ss, ct), _mm256_mul_pd(cc, st));
}
#endif

}  // namespace rollspec::spectral
