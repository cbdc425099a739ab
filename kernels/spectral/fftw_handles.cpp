#include "kernels/spectral/fftw_handles.hpp"

#include <fftw3.h>

#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace rollspec::spectral {

static_assert(std::is_same_v<FftwComplex, fftw_complex>, "FftwComplex must be fftw_complex");

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

namespace detail {
void* fftw_checked_malloc(std::size_t n, std::size_t element_bytes) {
  if (n == 0) return nullptr;
  if (n > std::numeric_limits<std::size_t>::max() / element_bytes) throw std::bad_alloc();  // n * size wraps
  void* p = fftw_malloc(n * element_bytes);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
void fftw_release(void* p) noexcept {
  if (p != nullptr) fftw_free(p);
}
void fftw_destroy(fftw_plan_s* plan) noexcept {
  if (plan == nullptr) return;
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_destroy_plan(plan);
}
}  // namespace detail

void FftwPlan::fail(const char* what) { throw std::runtime_error(std::string(what) + ": FFTW could not make a plan"); }

}  // namespace rollspec::spectral
