#include "kernels/spectral/tabulated_math_avx512.hpp"

#include <cstdint>

#if defined(ROLLSPEC_HAVE_AVX2_PATH)
#define ROLLSPEC_AVX512 __attribute__((target("avx512f")))
#endif

namespace rollspec::spectral {

#if defined(ROLLSPEC_HAVE_AVX2_PATH)
namespace {
ROLLSPEC_AVX512 inline __m512d k8(double x) { return _mm512_set1_pd(x); }
ROLLSPEC_AVX512 inline __m512i k8i(std::int64_t x) { return _mm512_set1_epi64(x); }

// Four 16-byte pairs (p0, p1, p2, p3) into one register, in that order.
ROLLSPEC_AVX512 inline __m512d four_pairs(const void* p0, const void* p1, const void* p2, const void* p3) {
  const auto ld = [](const void* p) { return _mm_loadu_pd(static_cast<const double*>(p)); };
  const __m256d lo = _mm256_insertf128_pd(_mm256_castpd128_pd256(ld(p0)), ld(p1), 1);
  const __m256d hi = _mm256_insertf128_pd(_mm256_castpd128_pd256(ld(p2)), ld(p3), 1);
  return _mm512_insertf64x4(_mm512_castpd256_pd512(lo), hi, 1);
}

// Eight 16-byte table pairs at byte offsets off[0..7] from base into (first of each, second of each).
ROLLSPEC_AVX512 inline void gather_pairs(const char* base, const std::int64_t* off, __m512d& first, __m512d& second) {
  const __m512d even = four_pairs(base + off[0], base + off[2], base + off[4], base + off[6]);
  const __m512d odd = four_pairs(base + off[1], base + off[3], base + off[5], base + off[7]);
  first = _mm512_unpacklo_pd(even, odd);
  second = _mm512_unpackhi_pd(even, odd);
}

// D-24, eight lanes. e + 1 and m come from getexp / getmant (exact, the same values as the
// scalar form's bit arithmetic); the bin centre c = 1 + (i + 1/2)/256 is m's top eight mantissa
// bits with the next one set, except in the top bin (c = 2); 1/c and ln(c/2) are loaded.
ROLLSPEC_AVX512 inline __m512d neg_log_open8(__m512d u, const TabulatedMath& t) {
  using namespace tabulated_detail;
  const __m512i bits = _mm512_castpd_si512(u);
  const __m512d e1 = _mm512_add_pd(_mm512_getexp_pd(u), k8(1.0));
  const __m512d m = _mm512_getmant_pd(u, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src);
  alignas(64) std::int64_t off[8];  // byte offset of each lane's bin (32 bytes a bin)
  _mm512_store_si512(off, _mm512_and_si512(_mm512_srli_epi64(bits, 44 - 5), k8i(255 << 5)));
  __m512d inverse, half_centre;  // adjacent in a LogBin
  gather_pairs(reinterpret_cast<const char*>(&t.log_bin[0].inverse), off, inverse, half_centre);
  const __m512i top_bits = _mm512_and_si512(bits, k8i(0x000ff00000000000LL));
  const __m512d centre_low = _mm512_castsi512_pd(_mm512_or_si512(top_bits, k8i(0x3ff0080000000000LL)));
  const __m512d centre = _mm512_mask_blend_pd(_mm512_cmpeq_epi64_mask(top_bits, k8i(0x000ff00000000000LL)), centre_low, k8(2.0));
  const __m512d r = _mm512_mul_pd(_mm512_sub_pd(m, centre), inverse);
  __m512d p = _mm512_sub_pd(k8(1.0 / 6.0), _mm512_mul_pd(r, k8(1.0 / 7.0)));
  p = _mm512_sub_pd(k8(0.2), _mm512_mul_pd(r, p));
  p = _mm512_sub_pd(k8(0.25), _mm512_mul_pd(r, p));
  p = _mm512_sub_pd(k8(1.0 / 3.0), _mm512_mul_pd(r, p));
  p = _mm512_sub_pd(k8(0.5), _mm512_mul_pd(r, p));
  p = _mm512_sub_pd(k8(1.0), _mm512_mul_pd(r, p));
  p = _mm512_mul_pd(r, p);
  const __m512d sum = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(e1, k8(ln2_hi)), half_centre),
                                    _mm512_add_pd(_mm512_mul_pd(e1, k8(ln2_lo)), p));
  return _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(sum), k8i(INT64_MIN)));
}

// D-25, eight lanes.
ROLLSPEC_AVX512 inline void sincos_two_pi8(__m512d v, const TabulatedMath& tab, __m512d& c, __m512d& s) {
  using namespace tabulated_detail;
  const __m512d x = _mm512_mul_pd(v, k8(1024.0));
  // k = trunc(x + 1/2) kept as a double (the scalar form's int32 k, converted back exactly).
  const __m512d k = _mm512_roundscale_pd(_mm512_add_pd(x, k8(0.5)), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
  const __m512d t = _mm512_mul_pd(_mm512_sub_pd(x, k), k8(phase_step));
  const __m512d t2 = _mm512_mul_pd(t, t);
  __m512d ct = _mm512_sub_pd(k8(1.0 / 24.0), _mm512_mul_pd(t2, k8(1.0 / 720.0)));
  ct = _mm512_sub_pd(k8(0.5), _mm512_mul_pd(t2, ct));
  ct = _mm512_sub_pd(k8(1.0), _mm512_mul_pd(t2, ct));
  __m512d st = _mm512_sub_pd(k8(1.0 / 120.0), _mm512_mul_pd(t2, k8(1.0 / 5040.0)));
  st = _mm512_sub_pd(k8(1.0 / 6.0), _mm512_mul_pd(t2, st));
  st = _mm512_sub_pd(t, _mm512_mul_pd(_mm512_mul_pd(t, t2), st));
  // Byte offset of each lane's (C_k, S_k), 16 bytes a pair: k + 2^52 has k in its low mantissa bits.
  alignas(64) std::int64_t off[8];
  _mm512_store_si512(off, _mm512_and_si512(_mm512_slli_epi64(_mm512_castpd_si512(_mm512_add_pd(k, k8(0x1p52))), 4), k8i(1023 << 4)));
  __m512d cc, ss;
  gather_pairs(reinterpret_cast<const char*>(tab.cos_sin), off, cc, ss);
  c = _mm512_sub_pd(_mm512_mul_pd(cc, ct), _mm512_mul_pd(ss, st));
  s = _mm512_add_pd(_mm512_mul_pd(ss, ct), _mm512_mul_pd(cc, st));
}
}  // namespace

bool cpu_has_avx512f() {
  static const bool yes = __builtin_cpu_supports("avx512f");
  return yes;
}

ROLLSPEC_AVX512 std::size_t fill_spectrum_avx512(std::size_t j, std::size_t end, const double* half_amplitudes,
                                                 bool rayleigh, const double* u_phase, const double* u_amplitude,
                                                 const TabulatedMath& t, FftwComplex* spec) {
  const __m512i first = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), second = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
  for (; j + 8 <= end; j += 8) {
    __m512d a = _mm512_loadu_pd(half_amplitudes + j);
    if (rayleigh)
      a = _mm512_mul_pd(a, _mm512_sqrt_pd(_mm512_max_pd(neg_log_open8(_mm512_loadu_pd(u_amplitude + j), t), _mm512_setzero_pd())));
    __m512d c, s;
    sincos_two_pi8(_mm512_loadu_pd(u_phase + j), t, c, s);
    const __m512d re = _mm512_mul_pd(a, c), im = _mm512_mul_pd(a, s);
    _mm512_storeu_pd(spec[j], _mm512_permutex2var_pd(re, first, im));  // (re, im) of j .. j + 3
    _mm512_storeu_pd(spec[j + 4], _mm512_permutex2var_pd(re, second, im));
  }
  return j;
}

ROLLSPEC_AVX512 void neg_log_open_x8(const double* u, const TabulatedMath& t, double* out) {
  _mm512_storeu_pd(out, neg_log_open8(_mm512_loadu_pd(u), t));
}

ROLLSPEC_AVX512 void sincos_two_pi_x8(const double* v, const TabulatedMath& t, double* c, double* s) {
  __m512d vc, vs;
  sincos_two_pi8(_mm512_loadu_pd(v), t, vc, vs);
  _mm512_storeu_pd(c, vc);
  _mm512_storeu_pd(s, vs);
}
#else
bool cpu_has_avx512f() { return false; }
std::size_t fill_spectrum_avx512(std::size_t j, std::size_t, const double*, bool, const double*, const double*,
                                 const TabulatedMath&, FftwComplex*) {
  return j;
}
void neg_log_open_x8(const double*, const TabulatedMath&, double*) {}
void sincos_two_pi_x8(const double*, const TabulatedMath&, double*, double*) {}
#endif

}  // namespace rollspec::spectral
