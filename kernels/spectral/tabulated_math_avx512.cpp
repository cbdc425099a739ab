#include "kernels/spectral/tabulated_math_avx512.hpp"

#include <cstdint>
#include <cstring>

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

// D-24 on N groups of eight lanes, the groups' operations interleaved step by step: each Horner
// step waits on the one before, so one group alone leaves the vector ports idle most of the time
// (a 4096-sample fill took as long as its FFT). e + 1 and m come from getexp / getmant (exact,
// the same values as the scalar form's bit arithmetic); the bin centre c = 1 + (i + 1/2)/256 is
// m's top eight mantissa bits with the next one set, except in the top bin (c = 2); 1/c and
// ln(c/2) are loaded. (e + 1) ln2_hi is exact, so adding ln(c/2) to it by one fused multiply-add
// rounds exactly as the scalar form's product-then-sum does.
template <int N>
ROLLSPEC_AVX512 __attribute__((always_inline)) inline void neg_log_open8(const double* u_mem, const TabulatedMath& t,
                                                                         __m512d (&out)[N]) {
  using namespace tabulated_detail;
  __m512d u[N], e1[N], r[N], p[N], half_centre[N];
  for (int g = 0; g < N; ++g) u[g] = _mm512_loadu_pd(u_mem + 8 * g);
  for (int g = 0; g < N; ++g) {
    const __m512i bits = _mm512_castpd_si512(u[g]);
    e1[g] = _mm512_add_pd(_mm512_getexp_pd(u[g]), k8(1.0));
    const __m512d m = _mm512_getmant_pd(u[g], _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src);
    // Byte offset of each lane's bin (32 bytes a bin) from u's bits in memory, by scalar integer
    // operations: moving eight indices out of a vector register costs the vector ports.
    const double* lane = u_mem + 8 * g;
    const auto off = [lane](int l) {
      std::uint64_t b;
      std::memcpy(&b, lane + l, sizeof b);
      return static_cast<std::size_t>((b >> (44 - 5)) & (255u << 5));
    };
    const char* base = reinterpret_cast<const char*>(&t.log_bin[0].inverse);
    const __m512d even = four_pairs(base + off(0), base + off(2), base + off(4), base + off(6));
    const __m512d odd = four_pairs(base + off(1), base + off(3), base + off(5), base + off(7));
    const __m512d inverse = _mm512_unpacklo_pd(even, odd);  // adjacent to half_centre in a LogBin
    half_centre[g] = _mm512_unpackhi_pd(even, odd);
    const __m512i top_bits = _mm512_and_si512(bits, k8i(0x000ff00000000000LL));
    const __m512d centre_low = _mm512_castsi512_pd(_mm512_or_si512(top_bits, k8i(0x3ff0080000000000LL)));
    const __m512d centre =
        _mm512_mask_blend_pd(_mm512_cmpeq_epi64_mask(top_bits, k8i(0x000ff00000000000LL)), centre_low, k8(2.0));
    r[g] = _mm512_mul_pd(_mm512_sub_pd(m, centre), inverse);
  }
  for (int g = 0; g < N; ++g) p[g] = _mm512_sub_pd(k8(1.0 / 6.0), _mm512_mul_pd(r[g], k8(1.0 / 7.0)));
  for (int g = 0; g < N; ++g) p[g] = _mm512_sub_pd(k8(0.2), _mm512_mul_pd(r[g], p[g]));
  for (int g = 0; g < N; ++g) p[g] = _mm512_sub_pd(k8(0.25), _mm512_mul_pd(r[g], p[g]));
  for (int g = 0; g < N; ++g) p[g] = _mm512_sub_pd(k8(1.0 / 3.0), _mm512_mul_pd(r[g], p[g]));
  for (int g = 0; g < N; ++g) p[g] = _mm512_sub_pd(k8(0.5), _mm512_mul_pd(r[g], p[g]));
  for (int g = 0; g < N; ++g) p[g] = _mm512_sub_pd(k8(1.0), _mm512_mul_pd(r[g], p[g]));
  for (int g = 0; g < N; ++g) {
    p[g] = _mm512_mul_pd(r[g], p[g]);
    const __m512d sum = _mm512_add_pd(_mm512_fmadd_pd(e1[g], k8(ln2_hi), half_centre[g]),
                                      _mm512_add_pd(_mm512_mul_pd(e1[g], k8(ln2_lo)), p[g]));
    out[g] = _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(sum), k8i(INT64_MIN)));
  }
}

// D-25 on N groups of eight lanes, interleaved likewise. k = trunc(1024 v + 1/2) as the scalar
// form has it: y = 1024 v + 1/2 by one fused multiply-add (1024 v is exact, so this is the
// scalar form's rounded sum), then y + 2^52 rounded down = 2^52 + k exactly (0 <= y <= 1024.5),
// whose low mantissa bits are k; 1024 v - k again by a fused multiply-add (exact either way).
template <int N>
ROLLSPEC_AVX512 __attribute__((always_inline)) inline void sincos_two_pi8(const __m512d (&v)[N],
                                                                          const TabulatedMath& tab, __m512d (&c)[N],
                                                                          __m512d (&s)[N]) {
  using namespace tabulated_detail;
  __m512d t[N], t2[N], ct[N], st[N], cc[N], ss[N];
  for (int g = 0; g < N; ++g) {
    const __m512d k_plus = _mm512_add_round_pd(_mm512_fmadd_pd(v[g], k8(1024.0), k8(0.5)), k8(0x1p52),
                                               _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    // Byte offset of each lane's (C_k, S_k), 16 bytes a pair.
    alignas(64) std::int64_t off[8];
    _mm512_store_si512(off, _mm512_and_si512(_mm512_slli_epi64(_mm512_castpd_si512(k_plus), 4), k8i(1023 << 4)));
    gather_pairs(reinterpret_cast<const char*>(tab.cos_sin), off, cc[g], ss[g]);
    const __m512d k = _mm512_sub_pd(k_plus, k8(0x1p52));
    t[g] = _mm512_mul_pd(_mm512_fmsub_pd(v[g], k8(1024.0), k), k8(phase_step));
  }
  for (int g = 0; g < N; ++g) t2[g] = _mm512_mul_pd(t[g], t[g]);
  for (int g = 0; g < N; ++g) ct[g] = _mm512_sub_pd(k8(1.0 / 24.0), _mm512_mul_pd(t2[g], k8(1.0 / 720.0)));
  for (int g = 0; g < N; ++g) st[g] = _mm512_sub_pd(k8(1.0 / 120.0), _mm512_mul_pd(t2[g], k8(1.0 / 5040.0)));
  for (int g = 0; g < N; ++g) ct[g] = _mm512_sub_pd(k8(0.5), _mm512_mul_pd(t2[g], ct[g]));
  for (int g = 0; g < N; ++g) st[g] = _mm512_sub_pd(k8(1.0 / 6.0), _mm512_mul_pd(t2[g], st[g]));
  for (int g = 0; g < N; ++g) ct[g] = _mm512_sub_pd(k8(1.0), _mm512_mul_pd(t2[g], ct[g]));
  for (int g = 0; g < N; ++g) st[g] = _mm512_sub_pd(t[g], _mm512_mul_pd(_mm512_mul_pd(t[g], t2[g]), st[g]));
  for (int g = 0; g < N; ++g) {
    c[g] = _mm512_sub_pd(_mm512_mul_pd(cc[g], ct[g]), _mm512_mul_pd(ss[g], st[g]));
    s[g] = _mm512_add_pd(_mm512_mul_pd(ss[g], ct[g]), _mm512_mul_pd(cc[g], st[g]));
  }
}

// Harmonics [j, j + 8N): spec = h sqrt(-ln u) (cos 2 pi v, sin 2 pi v).
template <int N>
ROLLSPEC_AVX512 __attribute__((always_inline)) inline void fill_groups(std::size_t j, const double* half_amplitudes,
                                                                       bool rayleigh, const double* u_phase,
                                                                       const double* u_amplitude,
                                                                       const TabulatedMath& t, FftwComplex* spec) {
  __m512d a[N], v[N], c[N], s[N];
  for (int g = 0; g < N; ++g) a[g] = _mm512_loadu_pd(half_amplitudes + j + 8 * g);
  if (rayleigh) {
    __m512d l[N];
    neg_log_open8<N>(u_amplitude + j, t, l);
    for (int g = 0; g < N; ++g) a[g] = _mm512_mul_pd(a[g], _mm512_sqrt_pd(_mm512_max_pd(l[g], _mm512_setzero_pd())));
  }
  for (int g = 0; g < N; ++g) v[g] = _mm512_loadu_pd(u_phase + j + 8 * g);
  sincos_two_pi8<N>(v, t, c, s);
  const __m512i first = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
  const __m512i second = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
  for (int g = 0; g < N; ++g) {
    const __m512d re = _mm512_mul_pd(a[g], c[g]), im = _mm512_mul_pd(a[g], s[g]);
    _mm512_storeu_pd(spec[j + 8 * g], _mm512_permutex2var_pd(re, first, im));  // (re, im) of j .. j + 3
    _mm512_storeu_pd(spec[j + 8 * g + 4], _mm512_permutex2var_pd(re, second, im));
  }
}
}  // namespace

bool cpu_has_avx512f() {
  static const bool yes = __builtin_cpu_supports("avx512f");
  return yes;
}

ROLLSPEC_AVX512 std::size_t fill_spectrum_avx512(std::size_t j, std::size_t end, const double* half_amplitudes,
                                                 bool rayleigh, const double* u_phase, const double* u_amplitude,
                                                 const TabulatedMath& t, FftwComplex* spec) {
  // Two groups (16 harmonics) a step: one leaves the ports idle; three or four were no faster.
  for (; j + 16 <= end; j += 16) fill_groups<2>(j, half_amplitudes, rayleigh, u_phase, u_amplitude, t, spec);
  for (; j + 8 <= end; j += 8) fill_groups<1>(j, half_amplitudes, rayleigh, u_phase, u_amplitude, t, spec);
  return j;
}

ROLLSPEC_AVX512 void neg_log_open_x8(const double* u, const TabulatedMath& t, double* out) {
  __m512d l[1];
  neg_log_open8<1>(u, t, l);
  _mm512_storeu_pd(out, l[0]);
}

ROLLSPEC_AVX512 void sincos_two_pi_x8(const double* v, const TabulatedMath& t, double* c, double* s) {
  const __m512d in[1] = {_mm512_loadu_pd(v)};
  __m512d vc[1], vs[1];
  sincos_two_pi8<1>(in, t, vc, vs);
  _mm512_storeu_pd(c, vc[0]);
  _mm512_storeu_pd(s, vs[0]);
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
