#include "kernels/beam/linear_reference.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/linear_response.hpp"
#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/welch_expectation.hpp"

namespace rollspec::beam {

double catmull_rom_gain(double tau, double theta) {
  // weights of y_{i-1}, y_i, y_{i+1}, y_{i+2} at fraction tau (Hermite basis, B13)
  const double t2 = tau * tau, t3 = t2 * tau;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + tau, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  const double c[4] = {-0.5 * h10, h00 - 0.5 * h11, h01 + 0.5 * h10, 0.5 * h11};
  std::complex<double> g = 0.0;
  for (int n = 0; n < 4; ++n) g += c[n] * std::polar(1.0, static_cast<double>(n - 1) * theta);
  return std::norm(g);
}

std::vector<double> reference_excitation(const ReferenceExcitation& e, const std::vector<double>& fine) {
  const double v = e.speed, dx = e.spacing, k_nyq = M_PI / dx;
  // Offset of the integration steps from the F0 samples (the same at every step when the samples
  // are one per step, the default); otherwise F0 is read at every fraction: mean gain over tau.
  const double dt_f0 = dx / v;
  const bool one_per_step = std::abs(dt_f0 / e.step - 1.0) < 1e-9;
  double tau = 0.0;
  if (one_per_step) {
    const double first = std::floor(e.x_start / dx);
    tau = (e.x_start - first * dx) / dx;
    tau -= std::floor(tau);
  }
  std::vector<double> exc(fine.size(), 0.0);
  for (std::size_t i = 1; i < fine.size(); ++i) {
    if (e.blocked_force) {
      exc[i] = e.time_psd(fine[i]);  // synthesised at the step, up to its Nyquist frequency
      continue;
    }
    const double k = 2.0 * M_PI * fine[i] / v;
    if (k > k_nyq) continue;  // harmonics above pi/dx are not synthesised
    const double patch = contact_patch_transfer(k, e.patch_half_width, dx);  // (B35a)
    const double theta = 2.0 * M_PI * fine[i] * dt_f0;
    double hold = 0.0;
    if (one_per_step) {
      hold = catmull_rom_gain(tau, theta);
    } else {
      for (int j = 0; j < 16; ++j) hold += catmull_rom_gain((j + 0.5) / 16.0, theta) / 16.0;
    }
    exc[i] = e.k0 * e.k0 * e.time_psd(fine[i]) * patch * patch * hold;
  }
  return exc;
}

PositionBlocks welch_position_blocks(const spectral::WelchPlan& plan, std::size_t n, std::size_t skip, double x_start,
                                     double v, double fs, std::size_t max_blocks) {
  // sample i of the analysed part weighs sum_segments w^2(i - segment start); the samples after
  // the last segment weigh nothing
  const auto tw = spectral::welch_time_weights(plan, n);
  const std::size_t blocks = std::min<std::size_t>(n, max_blocks), per = (n + blocks - 1) / blocks;
  PositionBlocks out;
  for (std::size_t b0 = 0; b0 < n; b0 += per) {
    const std::size_t b1 = std::min(n, b0 + per);
    double sw = 0.0, sx = 0.0;
    for (std::size_t i = b0; i < b1; ++i) {
      const double x = x_start + v * static_cast<double>(skip + i) / fs;
      sw += tw[i];
      sx += tw[i] * x;
    }
    out.edges.push_back(b0);
    out.position.push_back(sw > 0.0 ? sx / sw : x_start + v * static_cast<double>(skip + (b0 + b1) / 2) / fs);
    out.weight.push_back(sw);
  }
  out.edges.push_back(n);
  return out;
}

namespace {
// A PSD computed at fine indices `at` (every index up to `half`, then sparser) on every fine index:
// log-linear between computed points above `half` (linear where a value is 0).
std::vector<double> on_fine_grid(const std::vector<double>& v, const std::vector<std::size_t>& at, std::size_t nfine,
                                 std::size_t half) {
  std::vector<double> out(nfine, 0.0);
  std::copy(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(half + 1), out.begin());
  for (std::size_t i = half; i + 1 < at.size(); ++i) {
    const std::size_t a = at[i], b = at[i + 1];
    const double va = v[i], vb = v[i + 1];
    for (std::size_t j = a + 1; j <= b; ++j) {
      const double t = static_cast<double>(j - a) / static_cast<double>(b - a);
      out[j] = (va > 0.0 && vb > 0.0) ? va * std::pow(vb / va, t) : va + t * (vb - va);
    }
  }
  return out;
}
}  // namespace

std::size_t linear_reference_steps(const LinearReferenceInput& in) {
  return 1 + in.sensors.size() + (in.sensor_mean ? 1 : 0) + in.positions.count();
}

LinearReference linear_reference(const LinearReferenceInput& in, const std::function<void()>& step) {
  if (!in.beam || !in.welch) throw std::invalid_argument("linear_reference: no beam or Welch plan");
  auto done = [&] {
    if (step) step();
  };
  const spectral::WelchPlan& welch = *in.welch;
  const ReferenceExcitation& ex = in.excitation;
  const std::size_t refine = in.refine, nf = welch.n_freq(), half = refine * (nf - 1);
  const double fs = in.sample_rate;
  const auto aliases = static_cast<std::size_t>(std::ceil(0.5 / ex.step / (0.5 * fs) - 1e-9));
  const std::size_t nfine = half * aliases + 1;
  const double dfine = welch.frequency_step() / static_cast<double>(refine);
  // Above f_s/2 the PSD only aliases into the band, and it is smooth there unless modes lie there:
  // it is computed every `stride` fine points, at least 4 per half-power width 2 zeta f of any mode
  // above f_s/2 (one per Welch bin without such modes), and interpolated log-linearly.
  std::size_t stride = refine;
  for (int i = 0; i < in.beam->modes(); ++i) {
    const double f = in.beam->frequency(i);
    if (f > 0.5 * fs) stride = std::min(stride, std::max<std::size_t>(1, static_cast<std::size_t>(2.0 * in.beam->zeta(i) * f / (4.0 * dfine))));
  }
  std::vector<std::size_t> at;  // fine indices computed: the whole band, then every stride-th, and the last
  for (std::size_t j = 0; j <= half; ++j) at.push_back(j);
  for (std::size_t j = half + stride; j < nfine; j += stride) at.push_back(j);
  if (at.back() != nfine - 1) at.push_back(nfine - 1);
  std::vector<double> fine(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) fine[i] = dfine * static_cast<double>(at[i]);
  const std::vector<double> exc = reference_excitation(ex, fine);
  const PositionBlocks& pos = in.positions;
  const std::vector<std::size_t>& edges = pos.edges;
  const std::size_t n = edges.back();

  const std::size_t ns = in.sensors.size(), pairs = ns * (ns + 1) / 2, reach = 4 * refine, nb = half + 1;
  // Above the band the PSD alone (it only aliases into the band): the plain modal sum.
  const std::vector<double> above(fine.begin() + static_cast<std::ptrdiff_t>(nb), fine.end());
  const std::vector<double> exc_above(exc.begin() + static_cast<std::ptrdiff_t>(nb), exc.end());
  std::vector<std::vector<double>> psd_above(ns);
  if (!above.empty())
    psd_above = linear_response_psd(*in.beam, in.ball_mass, ex.k0, in.damping, pos.position, in.sensors, above, exc_above,
                                    Excitation::blocked_force, pos.weight).sensor_psd;
  done();
  // In the band, per position block: the transfers H_s, their products exc H_1 conj(H_2) (the
  // pairs (s, s) give the PSD, position-weighted as linear_response_psd weighs them), and the
  // cross-spectra smoothed by the Welch kernel truncated at +-4 bins for the dof (B34b below).
  const auto kern = spectral::welch_kernel(welch, refine);
  const std::size_t nk = kern.size();
  const std::vector<double> band(fine.begin(), fine.begin() + static_cast<std::ptrdiff_t>(nb));
  // The truncated kernel's taps by offset c - j in [-reach, reach] and, per bin, their sum over the
  // offsets inside [0, half]: the same for every block.
  std::vector<double> taps(2 * reach + 1), norm(nf, 0.0);
  for (std::size_t d = 0; d <= 2 * reach; ++d) taps[d] = kern[(nk + d - reach) % nk];
  for (std::size_t k = 0; k < nf; ++k) {
    const std::size_t c = k * refine, j0 = c > reach ? c - reach : 0, j1 = std::min(half, c + reach);
    for (std::size_t j = j0; j <= j1; ++j) norm[k] += taps[c + reach - j];
  }
  double weight_sum = 0.0;
  for (double v : pos.weight) weight_sum += v;
  if (!(weight_sum > 0.0)) throw std::invalid_argument("linear_reference: position weights sum to 0");
  std::vector<std::vector<double>> psd_band(ns, std::vector<double>(nb, 0.0));
  std::vector<std::complex<double>> cross((edges.size() - 1) * pairs * nf, 0.0);
  const auto modal = modal_receptances(*in.beam, band);  // shared by every block
  const auto blocks = static_cast<std::ptrdiff_t>(edges.size() - 1);
  // Blocks are independent but for the PSD sum, which the ordered section adds in block order:
  // the same result on any number of threads.
#pragma omp parallel
  {
  // Products per fine frequency, pair-major ([j][q], re and im): the kernel's sums run over
  // contiguous pairs.
  std::vector<double> product(2 * pairs * nb), acc(2 * pairs);
#pragma omp for schedule(static, 1) ordered
  for (std::ptrdiff_t pp = 0; pp < blocks; ++pp) {
    const auto p = static_cast<std::size_t>(pp);
    const bool seen = pos.weight[p] > 0.0;  // a block no segment sees weighs nothing
    if (seen) {
      const auto H = linear_response_transfer(*in.beam, in.ball_mass, ex.k0, in.damping, pos.position[p], in.sensors,
                                              band, Excitation::blocked_force, &modal);
      for (std::size_t j = 0; j < nb; ++j) {
        double* pj = product.data() + 2 * pairs * j;
        std::size_t q = 0;
        for (std::size_t s1 = 0; s1 < ns; ++s1)
          for (std::size_t s2 = s1; s2 < ns; ++s2, ++q) {
            const std::complex<double> v = exc[j] * H[s1][j] * std::conj(H[s2][j]);
            pj[2 * q] = v.real();
            pj[2 * q + 1] = v.imag();
          }
      }
    }
#pragma omp ordered
    {
      if (seen) {
        const double wp = pos.weight[p] / weight_sum;
        for (std::size_t s = 0; s < ns; ++s) {
          const std::size_t q = s * ns - s * (s - 1) / 2;  // the (s, s) pair
          for (std::size_t j = 0; j < nb; ++j) psd_band[s][j] += wp * product[2 * (pairs * j + q)];
        }
      }
      done();
    }
    if (!seen) continue;
    for (std::size_t k = 0; k < nf; ++k) {
      const std::size_t c = k * refine, j0 = c > reach ? c - reach : 0, j1 = std::min(half, c + reach);
      std::fill(acc.begin(), acc.end(), 0.0);
      for (std::size_t j = j0; j <= j1; ++j) {
        const double w = taps[c + reach - j];
        const double* pj = product.data() + 2 * pairs * j;
        for (std::size_t i = 0; i < 2 * pairs; ++i) acc[i] += w * pj[i];
      }
      for (std::size_t q = 0; q < pairs; ++q) cross[(p * pairs + q) * nf + k] = {acc[2 * q] / norm[k], acc[2 * q + 1] / norm[k]};
    }
  }
  }
  std::vector<std::vector<double>> rows_fine;
  for (std::size_t s = 0; s < ns; ++s) {
    std::vector<double> row = psd_band[s];
    row.insert(row.end(), psd_above[s].begin(), psd_above[s].end());
    rows_fine.push_back(on_fine_grid(row, at, nfine, half));
  }
  if (in.sensor_mean) {
    std::vector<double> m(nfine, 0.0);
    for (std::size_t r = 0; r < ns; ++r)
      for (std::size_t k = 0; k < nfine; ++k) m[k] += rows_fine[r][k] / static_cast<double>(ns);
    rows_fine.push_back(m);
  }
  LinearReference out;
  out.rows = rows_fine.size();
  out.bins = nf;
  for (const auto& row : rows_fine) {
    const auto e = spectral::welch_expectation(welch, row, refine);
    out.psd.insert(out.psd.end(), e.begin(), e.end());
    done();
    for (std::size_t k = 0; k < nf; ++k) out.raw.push_back(row[k * refine]);
  }
  // Degrees of freedom of the ensemble mean per bin (B34b): the record is not stationary (the
  // response at a bin rises and falls with the ball's position, e.g. with phi_n(xi)^2 at a
  // resonance), so a Welch estimate holds fewer dof than the stationary D-16 value; the sensors
  // of one roll are correlated, so their mean holds fewer than n_sensors times one sensor's.
  for (std::size_t s = 0; s < ns; ++s) {
    std::vector<std::complex<double>> own((edges.size() - 1) * nf);
    const std::size_t q = s * ns - s * (s - 1) / 2;  // the (s, s) pair
    for (std::size_t p = 0; p + 1 < edges.size(); ++p)
      for (std::size_t k = 0; k < nf; ++k) own[p * nf + k] = cross[(p * pairs + q) * nf + k];
    const auto d = spectral::welch_block_dof(welch, n, edges, 1, nf, own);
    for (double v1 : d) out.dof.push_back(in.realisations * v1);
  }
  if (in.sensor_mean) {
    const auto d = spectral::welch_block_dof(welch, n, edges, ns, nf, cross);
    for (double v1 : d) out.dof.push_back(in.realisations * v1);
  }
  out.mean_lower.resize(out.psd.size());
  out.mean_upper.resize(out.psd.size());
  for (std::size_t i = 0; i < out.psd.size(); ++i) {
    const auto fi = spectral::chi_square_interval(std::max(out.dof[i], 1.0), in.confidence);
    out.mean_lower[i] = out.psd[i] / fi.upper;
    out.mean_upper[i] = out.psd[i] / fi.lower;
  }
  return out;
}

}  // namespace rollspec::beam
