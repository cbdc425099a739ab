// The one FFTW layer: checked allocations, plans that refuse to be null, ownership that moves.
#include <doctest/doctest.h>
#include <fftw3.h>

#include <cstdint>
#include <new>
#include <stdexcept>

#include "kernels/spectral/fftw_handles.hpp"

using namespace rollspec::spectral;

TEST_CASE("FFTW buffers: aligned, checked, moved without a double free") {
  RealBuffer a(1000);
  REQUIRE(a.data() != nullptr);
  CHECK(a.size() == 1000);
  CHECK(reinterpret_cast<std::uintptr_t>(a.data()) % 16 == 0);  // fftw_malloc's SIMD alignment
  a[999] = 2.5;
  RealBuffer b(std::move(a));
  CHECK(a.data() == nullptr);
  CHECK(a.size() == 0);
  CHECK(b[999] == 2.5);
  CHECK(RealBuffer(0).data() == nullptr);
#if defined(__has_feature)  // Clang names AddressSanitizer with __has_feature, GCC with __SANITIZE_ADDRESS__
#if __has_feature(address_sanitizer)
#define ROLLSPEC_UNDER_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define ROLLSPEC_UNDER_ASAN 1
#endif
#if !defined(ROLLSPEC_UNDER_ASAN)  // AddressSanitizer reports an impossible size itself
  // 2^60 complex values are 2^64 bytes, a size that wraps to 0; 2^58 doubles (2^61 bytes) do not
  // wrap but cannot exist. Both are refused with std::bad_alloc, never a null or tiny buffer.
  CHECK_THROWS_AS(ComplexBuffer(std::size_t{1} << 60), std::bad_alloc);
  CHECK_THROWS_AS(RealBuffer(std::size_t{1} << 58), std::bad_alloc);
#endif
}

TEST_CASE("FFTW plans: a null plan is an error naming the transform; a plan runs and moves") {
  CHECK_THROWS_WITH_AS(FftwPlan([] { return static_cast<fftw_plan>(nullptr); }, "test transform"),
                       "test transform: FFTW could not make a plan", std::runtime_error);
  const std::size_t n = 8;
  RealBuffer in(n);
  ComplexBuffer out(n / 2 + 1);
  FftwPlan plan([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(n), in.data(), out.data(), FFTW_ESTIMATE); }, "r2c");
  FftwPlan moved(std::move(plan));
  CHECK(plan.get() == nullptr);
  for (std::size_t i = 0; i < n; ++i) in[i] = (i % 2 == 0) ? 1.0 : -1.0;  // the Nyquist tone
  fftw_execute(moved.get());
  CHECK(out[n / 2][0] == doctest::Approx(static_cast<double>(n)));
  for (std::size_t k = 0; k < n / 2; ++k) CHECK(out[k][0] == doctest::Approx(0.0));
}
