#include "kernels/spectral/welch_expectation.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::spectral {

namespace {
void check(const WelchPlan& plan, const std::vector<double>& fine, std::size_t refine) {
  if (refine < 1 || fine.size() < refine * (plan.n_freq() - 1) + 1)
    throw std::invalid_argument("welch_expectation: fine PSD must hold at least refine * (n_freq - 1) + 1 values");
}

// Trapezoid weights on the fine grid [0, f_s/2].
double trapezoid(std::size_t j, std::size_t n) { return (j == 0 || j + 1 == n) ? 0.5 : 1.0; }
}  // namespace

std::vector<double> welch_kernel(const WelchPlan& plan, std::size_t refine) {
  if (refine < 1) throw std::invalid_argument("welch_kernel: refine must be >= 1");
  const auto& w = plan.window();
  const std::size_t L = w.size(), N = L * refine;
  const double fs = plan.config().sample_rate;
  double s2 = 0.0;
  for (double v : w) s2 += v * v;
  // K at nu = m f_s / N, m = 0..N-1 (periodic in m).
  std::vector<double> kernel(N);
  const RealBuffer in(N);
  const ComplexBuffer out(N / 2 + 1);
  const FftwPlan p([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(N), in.data(), out.data(), FFTW_ESTIMATE); },
                   "Welch kernel (r2c)");
  for (std::size_t i = 0; i < N; ++i) in[i] = i < L ? w[i] : 0.0;
  fftw_execute(p.get());
  for (std::size_t m = 0; m <= N / 2; ++m) {
    const double v = (out[m][0] * out[m][0] + out[m][1] * out[m][1]) / (fs * s2);
    kernel[m] = v;
    if (m > 0 && m < N - m) kernel[N - m] = v;  // K is even
  }
  return kernel;
}

// The integral on the fine grid is a circular convolution: with g_j = trapezoid_j S_j folded onto
// the circle of N = L refine points (S beyond f_s/2 aliases, K being N-periodic) and K even,
//   E[P_k] = df (C[M k] + C[-M k]),  C = g (*) K,
// one FFT product instead of n_freq x n_fine terms.
std::vector<double> welch_expectation(const WelchPlan& plan, const std::vector<double>& fine, std::size_t refine) {
  check(plan, fine, refine);
  const std::size_t N = plan.window().size() * refine, nf = plan.n_freq(), nfine = fine.size(), nc = N / 2 + 1;
  const double dfine = plan.config().sample_rate / static_cast<double>(N);
  const std::vector<double> kernel = welch_kernel(plan, refine);
  const RealBuffer g(N), k(N);
  const ComplexBuffer G(nc), K(nc);
  const int n = static_cast<int>(N);
  const FftwPlan forward_g([&] { return fftw_plan_dft_r2c_1d(n, g.data(), G.data(), FFTW_ESTIMATE); },
                           "Welch expectation (r2c)");
  const FftwPlan forward_k([&] { return fftw_plan_dft_r2c_1d(n, k.data(), K.data(), FFTW_ESTIMATE); },
                           "Welch expectation (r2c)");
  const FftwPlan backward([&] { return fftw_plan_dft_c2r_1d(n, G.data(), g.data(), FFTW_ESTIMATE); },
                          "Welch expectation (c2r)");
  std::fill(g.data(), g.data() + N, 0.0);
  for (std::size_t j = 0; j < nfine; ++j) g[j % N] += trapezoid(j, nfine) * fine[j];
  std::copy(kernel.begin(), kernel.end(), k.data());
  fftw_execute(forward_g.get());
  fftw_execute(forward_k.get());
  for (std::size_t m = 0; m < nc; ++m) {
    const double re = G[m][0] * K[m][0] - G[m][1] * K[m][1], im = G[m][0] * K[m][1] + G[m][1] * K[m][0];
    G[m][0] = re;
    G[m][1] = im;
  }
  fftw_execute(backward.get());  // unnormalised: N C
  std::vector<double> out(nf, 0.0);
  for (std::size_t i = 0; i < nf; ++i) {
    const std::size_t mk = (i * refine) % N;
    out[i] = std::max(0.0, (g[mk] + g[(N - mk) % N]) * dfine / static_cast<double>(N));
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

std::vector<double> welch_time_weights(const WelchPlan& plan, std::size_t n) {
  const std::size_t nb = plan.segments(n), L = plan.config().segment, hop = L - plan.config().overlap;
  if (nb == 0) throw std::invalid_argument("welch_time_weights: record shorter than one segment");
  const auto& w = plan.window();
  double s2 = 0.0;
  for (double v : w) s2 += v * v;
  std::vector<double> tw(n, 0.0);
  for (std::size_t a = 0; a < nb; ++a)
    for (std::size_t t = 0; t < L; ++t) tw[a * hop + t] += w[t] * w[t] / (static_cast<double>(nb) * s2);
  return tw;
}

WelchBlockTerms welch_block_terms(const WelchPlan& plan, std::size_t n, const std::vector<std::size_t>& edges) {
  const std::size_t nb = plan.segments(n), L = plan.config().segment, hop = L - plan.config().overlap;
  if (nb == 0) throw std::invalid_argument("welch_block_dof: record shorter than one segment");
  if (edges.size() < 2 || edges.front() != 0 || edges.back() != n)
    throw std::invalid_argument("welch_block_dof: block edges must run from 0 to n");
  for (std::size_t p = 1; p < edges.size(); ++p)
    if (edges[p] <= edges[p - 1]) throw std::invalid_argument("welch_block_dof: block edges must increase");
  const std::size_t blocks = edges.size() - 1;
  const auto& w = plan.window();
  double s2 = 0.0;
  for (double v : w) s2 += v * v;
  std::size_t mmax = 0;
  while ((mmax + 1) * hop < L) ++mmax;
  // u_ab(p) for b = a + m, m = 0..mmax: nonzero only for the blocks inside segment a
  // (kernels/beam README B34b).
  WelchBlockTerms out;
  out.segments = nb;
  for (std::size_t a = 0; a < nb; ++a)
    for (std::size_t m = 0; m <= mmax && a + m < nb; ++m) {
      const std::size_t lo = (a + m) * hop, hi = a * hop + L;  // samples in both segments
      const std::size_t g = out.group_m.size();
      std::size_t p = static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), lo) - edges.begin()) - 1;
      bool any = false;
      for (; p < blocks && edges[p] < hi; ++p) {
        double u = 0.0;
        for (std::size_t t = std::max(lo, edges[p]); t < std::min(hi, edges[p + 1]); ++t)
          u += w[t - a * hop] * w[t - (a + m) * hop];
        if (u != 0.0) {
          out.terms.push_back({g, p, u / s2});
          any = true;
        }
      }
      if (any) out.group_m.push_back(m);
    }
  return out;
}

std::vector<double> welch_group_dof(const WelchBlockTerms& t, std::size_t channels, std::size_t bins,
                                    const std::vector<std::complex<double>>& grouped) {
  const std::size_t pairs = channels * (channels + 1) / 2, groups = t.group_m.size();
  if (channels < 1 || grouped.size() != groups * pairs * bins)
    throw std::invalid_argument("welch_group_dof: need groups x channel pairs x bins cross-spectra");
  std::vector<double> dof(bins, 0.0);
  for (std::size_t k = 0; k < bins; ++k) {
    double mean = 0.0, var = 0.0;
    for (std::size_t g = 0; g < groups; ++g) {
      const std::complex<double>* c = grouped.data() + g * pairs * bins + k;  // c[q * bins]
      double sum = 0.0;  // sum over ordered channel pairs of |C_ab^{ss'}|^2
      std::size_t q = 0;
      for (std::size_t s = 0; s < channels; ++s)
        for (std::size_t s2i = s; s2i < channels; ++s2i, ++q) sum += (s2i == s ? 1.0 : 2.0) * std::norm(c[q * bins]);
      const bool diagonal = t.group_m[g] == 0;
      var += (diagonal ? 1.0 : 2.0) * sum;
      if (diagonal) {
        q = 0;
        for (std::size_t s = 0; s < channels; ++s)
          for (std::size_t s2i = s; s2i < channels; ++s2i, ++q)
            if (s2i == s) mean += c[q * bins].real();
      }
    }
    // E = mean / (nb channels), Var = var / (nb channels)^2: nu = 2 E^2 / Var = 2 mean^2 / var.
    dof[k] = var > 0.0 ? 2.0 * mean * mean / var : 0.0;
  }
  return dof;
}

std::vector<double> welch_block_dof(const WelchPlan& plan, std::size_t n, const std::vector<std::size_t>& edges,
                                    std::size_t channels, std::size_t bins,
                                    const std::vector<std::complex<double>>& cross) {
  const WelchBlockTerms t = welch_block_terms(plan, n, edges);
  const std::size_t pairs = channels * (channels + 1) / 2, blocks = edges.size() - 1;
  if (channels < 1 || cross.size() != blocks * pairs * bins)
    throw std::invalid_argument("welch_block_dof: need blocks x channel pairs x bins cross-spectra");
  std::vector<std::complex<double>> grouped(t.group_m.size() * pairs * bins, 0.0);
  for (const auto& term : t.terms)
    for (std::size_t q = 0; q < pairs; ++q)
      for (std::size_t k = 0; k < bins; ++k)
        grouped[(term.group * pairs + q) * bins + k] += term.u * cross[(term.block * pairs + q) * bins + k];
  return welch_group_dof(t, channels, bins, grouped);
}

}  // namespace rollspec::spectral
