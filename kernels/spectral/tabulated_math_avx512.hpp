#pragma once
// Eight-lane (AVX-512F) forms of D-24 and D-25 and the D-3 spectrum fill built on them, for CPUs
// that report AVX-512F at run time (the build targets baseline x86-64). Each lane performs the
// scalar form's IEEE operations in the scalar form's order (tabulated_math.hpp), so the bits are
// the same on every machine; only the table look-ups and lane shuffles differ. The source file is
// compiled with -ffp-contract=off: AVX-512F has fused multiply-add, which would change the bits
// where the compiler chose it. It is written out only where the product is exact (e + 1 times
// ln2_hi, 1024 v), so that it rounds once, as the scalar form's product-then-sum does.
#include <cstddef>

#include "kernels/spectral/fftw_handles.hpp"
#include "kernels/spectral/tabulated_math.hpp"

namespace rollspec::spectral {

bool cpu_has_avx512f();  // AVX-512F usable here (CPU and operating system)

// Harmonics [j, end) eight at a time: spec[i] = h_i sqrt(-ln u_i) (cos 2 pi v_i, sin 2 pi v_i)
// (D-3; without the Rayleigh factor when !rayleigh). Returns the first harmonic not done (fewer
// than eight remain). Call only where cpu_has_avx512f().
std::size_t fill_spectrum_avx512(std::size_t j, std::size_t end, const double* half_amplitudes, bool rayleigh,
                                 const double* u_phase, const double* u_amplitude, const TabulatedMath& t,
                                 FftwComplex* spec);

// Eight lanes of neg_log_open (u: positive normal doubles below 1) and of sincos_two_pi, for the
// tests that compare them with the scalar forms. Call only where cpu_has_avx512f().
void neg_log_open_x8(const double* u, const TabulatedMath& t, double* out);
void sincos_two_pi_x8(const double* v, const TabulatedMath& t, double* c, double* s);

}  // namespace rollspec::spectral
