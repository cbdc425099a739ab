#pragma once
// The one FFTW layer of rollspec: buffers from fftw_malloc and plans, each owned by an RAII type,
// so nothing leaks when an exception unwinds; every allocation is checked (std::bad_alloc) and
// every plan too (std::runtime_error). FFTW's planner is not thread-safe: every plan creation and
// destruction takes the one lock of planner_mutex(). Executing a plan (the new-array interface on
// buffers from FftwBuffer, which all share fftw_malloc's alignment) needs no lock.
#include <cstddef>
#include <mutex>
#include <utility>

struct fftw_plan_s;  // fftw3.h: typedef struct fftw_plan_s* fftw_plan

namespace rollspec::spectral {

using FftwComplex = double[2];  // fftw3.h's fftw_complex (C99 complex layout)

std::mutex& fftw_planner_mutex();

namespace detail {
void* fftw_checked_malloc(std::size_t n, std::size_t element_bytes);  // throws std::bad_alloc, also on overflow
void fftw_release(void* p) noexcept;
void fftw_destroy(fftw_plan_s* plan) noexcept;  // under the planner lock
}  // namespace detail

// n elements of double or FftwComplex, uninitialised, from fftw_malloc.
template <class T>
class FftwBuffer {
 public:
  FftwBuffer() = default;
  explicit FftwBuffer(std::size_t n) : data_(static_cast<T*>(detail::fftw_checked_malloc(n, sizeof(T)))), size_(n) {}
  ~FftwBuffer() { detail::fftw_release(data_); }
  FftwBuffer(FftwBuffer&& o) noexcept : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  FftwBuffer& operator=(FftwBuffer&& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    return *this;
  }
  FftwBuffer(const FftwBuffer&) = delete;
  FftwBuffer& operator=(const FftwBuffer&) = delete;
  T* data() const { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};
using RealBuffer = FftwBuffer<double>;
using ComplexBuffer = FftwBuffer<FftwComplex>;

// An fftw_plan made by `make()` (any fftw_plan_* call) under the planner lock, destroyed under it.
class FftwPlan {
 public:
  FftwPlan() = default;
  template <class Make>
  explicit FftwPlan(Make&& make, const char* what) {
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      plan_ = make();
    }
    if (plan_ == nullptr) fail(what);
  }
  ~FftwPlan() { detail::fftw_destroy(plan_); }
  FftwPlan(FftwPlan&& o) noexcept : plan_(std::exchange(o.plan_, nullptr)) {}
  FftwPlan& operator=(FftwPlan&& o) noexcept {
    std::swap(plan_, o.plan_);
    return *this;
  }
  FftwPlan(const FftwPlan&) = delete;
  FftwPlan& operator=(const FftwPlan&) = delete;
  fftw_plan_s* get() const { return plan_; }

 private:
  [[noreturn]] static void fail(const char* what);
  fftw_plan_s* plan_ = nullptr;
};

}  // namespace rollspec::spectral
