#include "kernels/spectral/welch_expectation.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <stdexcept>

#include "kernels/spectral/fftw_planner_lock.hpp"

namespace rollspec::spectral {

namespace {
void check(const WelchPlan& plan, const std::vector<double>& fine, std::size_t refine) {
  if (refine < 1 || fine.size() != refine * (plan.n_freq() - 1) + 1)
    throw std::invalid_argument("welch_expectation: fine PSD must hold refine * (n_freq - 1) + 1 values");
}

// Trapezoid weights on the fine grid [0, f_s/2].
double trapezoid(std::size_t j, std::size_t n) { return (j == 0 || j + 1 == n) ? 0.5 : 1.0; }
}  // namespace

std::vector<double> welch_expectation(const WelchPlan& plan, const std::vector<double>& fine, std::size_t refine) {
  check(plan, fine, refine);
  const auto& w = plan.window();
  const std::size_t L = w.size(), N = L * refine, nf = plan.n_freq(), nfine = fine.size();
  const double fs = plan.config().sample_rate, dfine = fs / static_cast<double>(N);
  double s2 = 0.0;
  for (double v : w) s2 += v * v;
  // K at nu = m f_s / N, m = 0..N-1 (periodic in m).
  std::vector<double> kernel(N);
  {
    double* in = fftw_alloc_real(N);
    fftw_complex* out = fftw_alloc_complex(N / 2 + 1);
    fftw_plan p;
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      p = fftw_plan_dft_r2c_1d(static_cast<int>(N), in, out, FFTW_ESTIMATE);
    }
    for (std::size_t i = 0; i < N; ++i) in[i] = i < L ? w[i] : 0.0;
    fftw_execute(p);
    for (std::size_t m = 0; m <= N / 2; ++m) {
      const double v = (out[m][0] * out[m][0] + out[m][1] * out[m][1]) / (fs * s2);
      kernel[m] = v;
      if (m > 0 && m < N - m) kernel[N - m] = v;  // K is even
    }
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      fftw_destroy_plan(p);
    }
    fftw_free(in);
    fftw_free(out);
  }
  std::vector<double> out(nf, 0.0);
  for (std::size_t k = 0; k < nf; ++k) {
    const std::size_t mk = k * refine;  // f_k on the fine grid
    double acc = 0.0;
    for (std::size_t j = 0; j < nfine; ++j) {
      const std::size_t minus = (mk + N - j) % N, plus = (mk + j) % N;
      acc += trapezoid(j, nfine) * fine[j] * (kernel[minus] + kernel[plus]);
    }
    out[k] = acc * dfine;
  }
  return out;
}

std::vector<double> welch_expectation_direct(const WelchPlan& plan, const std::vector<double>& fine,
                                             std::size_t refine) {
  check(plan, fine, refine);
  const auto& w = plan.window();
  const std::size_t L = w.size(), nf = plan.n_freq(), nfine = fine.size();
  const double fs = plan.config().sample_rate, dfine = fs / static_cast<double>(L * refine);
  double s2 = 0.0;
  for (double v : w) s2 += v * v;
  auto K = [&](double nu) {
    std::complex<double> acc = 0.0;
    for (std::size_t i = 0; i < L; ++i) acc += w[i] * std::polar(1.0, -2.0 * M_PI * nu * static_cast<double>(i) / fs);
    return std::norm(acc) / (fs * s2);
  };
  std::vector<double> out(nf, 0.0);
  for (std::size_t k = 0; k < nf; ++k) {
    const double fk = plan.frequency_step() * static_cast<double>(k);
    for (std::size_t j = 0; j < nfine; ++j) {
      const double f = dfine * static_cast<double>(j);
      out[k] += trapezoid(j, nfine) * fine[j] * (K(fk - f) + K(fk + f)) * dfine;
    }
  }
  return out;
}

}  // namespace rollspec::spectral
