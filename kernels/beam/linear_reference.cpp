#include "kernels/beam/linear_reference.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "kernels/beam/linear_response.hpp"
#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/welch_expectation.hpp"

namespace rollspec::beam {

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

// The fine grid of D-20 (refine points per Welch bin, continued to the integration step's Nyquist
// frequency, B34c) and the points of it where the PSD is computed.
struct FineGrid {
  std::size_t nf = 0, half = 0, nfine = 0, nb = 0;  // Welch bins; last band index; fine points; band points
  std::vector<std::size_t> at;                      // computed fine indices: the whole band, then sparser
  std::vector<double> f;                            // their frequencies, Hz
};

FineGrid fine_grid(const LinearReferenceInput& in) {
  if (!in.beam || !in.welch) throw std::invalid_argument("linear_reference: no beam or Welch plan");
  const spectral::WelchPlan& welch = *in.welch;
  FineGrid g;
  g.nf = welch.n_freq();
  g.half = in.refine * (g.nf - 1);
  g.nb = g.half + 1;
  const auto aliases = static_cast<std::size_t>(std::ceil(0.5 / in.excitation.step / (0.5 * in.sample_rate) - 1e-9));
  g.nfine = g.half * aliases + 1;
  const double dfine = welch.frequency_step() / static_cast<double>(in.refine);
  // Above f_s/2 the PSD only aliases into the band, and it is smooth there unless modes lie there:
  // it is computed every `stride` fine points, at least 4 per half-power width 2 zeta f of any mode
  // above f_s/2 (one per Welch bin without such modes), and interpolated log-linearly.
  std::size_t stride = in.refine;
  for (int i = 0; i < in.beam->modes(); ++i) {
    const double f = in.beam->frequency(i);
    if (f > 0.5 * in.sample_rate)
      stride = std::min(stride,
                        std::max<std::size_t>(1, static_cast<std::size_t>(2.0 * in.beam->zeta(i) * f / (4.0 * dfine))));
  }
  for (std::size_t j = 0; j <= g.half; ++j) g.at.push_back(j);
  for (std::size_t j = g.half + stride; j < g.nfine; j += stride) g.at.push_back(j);
  if (g.at.back() != g.nfine - 1) g.at.push_back(g.nfine - 1);
  g.f.resize(g.at.size());
  for (std::size_t i = 0; i < g.at.size(); ++i) g.f[i] = dfine * static_cast<double>(g.at[i]);
  return g;
}

// The Welch kernel truncated at +-4 bins, by offset c - j in [-reach, reach], and per bin the sum
// of the taps whose offsets fall inside [0, half] (B34b: smoothed cross-spectra for the dof).
struct SmoothingKernel {
  std::size_t reach = 0;
  std::vector<double> taps, norm;
};

SmoothingKernel smoothing_kernel(const spectral::WelchPlan& welch, std::size_t refine, std::size_t half) {
  const auto kern = spectral::welch_kernel(welch, refine);
  const std::size_t nk = kern.size(), nf = welch.n_freq();
  SmoothingKernel s;
  s.reach = 4 * refine;
  s.taps.resize(2 * s.reach + 1);
  s.norm.assign(nf, 0.0);
  for (std::size_t d = 0; d <= 2 * s.reach; ++d) s.taps[d] = kern[(nk + d - s.reach) % nk];
  for (std::size_t k = 0; k < nf; ++k) {
    const std::size_t c = k * refine, j0 = c > s.reach ? c - s.reach : 0, j1 = std::min(half, c + s.reach);
    for (std::size_t j = j0; j <= j1; ++j) s.norm[k] += s.taps[c + s.reach - j];
  }
  return s;
}

double position_weight_sum(const PositionBlocks& pos) {
  double sum = 0.0;
  for (double v : pos.weight) sum += v;
  if (!(sum > 0.0)) throw std::invalid_argument("linear_reference: position weights sum to 0");
  return sum;
}

// From the sensors' PSDs at the computed points and the dof rows: the rows on the whole fine grid
// (plus their mean), their expected Welch estimates (D-20), the raw PSD at the bins and the
// ensemble mean's range (D-16).
LinearReference finish(const LinearReferenceInput& in, const FineGrid& g, const std::vector<std::vector<double>>& psd,
                       const std::vector<std::vector<double>>& dof, const std::function<void()>& done) {
  std::vector<std::vector<double>> rows_fine;
  for (const auto& row : psd) rows_fine.push_back(on_fine_grid(row, g.at, g.nfine, g.half));
  if (in.sensor_mean) {
    const std::size_t ns = psd.size();
    std::vector<double> m(g.nfine, 0.0);
    for (std::size_t r = 0; r < ns; ++r)
      for (std::size_t k = 0; k < g.nfine; ++k) m[k] += rows_fine[r][k] / static_cast<double>(ns);
    rows_fine.push_back(m);
  }
  LinearReference out;
  out.rows = rows_fine.size();
  out.bins = g.nf;
  for (const auto& row : rows_fine) {
    const auto e = spectral::welch_expectation(*in.welch, row, in.refine);
    out.psd.insert(out.psd.end(), e.begin(), e.end());
    done();
    for (std::size_t k = 0; k < g.nf; ++k) out.raw.push_back(row[k * in.refine]);
  }
  for (const auto& row : dof)
    for (double v : row) out.dof.push_back(in.realisations * v);
  out.mean_lower.resize(out.psd.size());
  out.mean_upper.resize(out.psd.size());
  for (std::size_t i = 0; i < out.psd.size(); ++i) {
    const auto fi = spectral::chi_square_interval(std::max(out.dof[i], 1.0), in.confidence);
    out.mean_lower[i] = out.psd[i] / fi.upper;
    out.mean_upper[i] = out.psd[i] / fi.lower;
  }
  return out;
}

// Fine points per unit of work of the fast path.
constexpr std::size_t chunk_points = 128;

// Ranges of computed points [lo, hi) that the fast path takes one at a time: the band (where the
// cross-spectra are needed) and above it (the PSD only) never share a range.
std::vector<std::pair<std::size_t, std::size_t>> point_ranges(std::size_t nb, std::size_t nc) {
  std::vector<std::pair<std::size_t, std::size_t>> r;
  for (std::size_t lo = 0; lo < nb; lo += chunk_points) r.emplace_back(lo, std::min(nb, lo + chunk_points));
  for (std::size_t lo = nb; lo < nc; lo += chunk_points) r.emplace_back(lo, std::min(nc, lo + chunk_points));
  return r;
}

// What every position block shares at the computed points: the modal receptances, mode-major
// (re and im planes), and the terms of (B32) that do not depend on the position.
struct PointTerms {
  std::size_t count = 0;
  std::vector<double> r_re, r_im;  // [mode * count + j]
  std::vector<double> w2, ball, ikc_re, ikc_im, kc_im;
};

PointTerms point_terms(const LinearReferenceInput& in, const std::vector<double>& f) {
  const ModalBeam& b = *in.beam;
  const auto n = static_cast<std::size_t>(b.modes());
  const std::vector<std::complex<double>> modal = modal_receptances(b, f);
  PointTerms t;
  t.count = f.size();
  t.r_re.resize(n * t.count);
  t.r_im.resize(n * t.count);
  for (std::size_t j = 0; j < t.count; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      t.r_re[i * t.count + j] = modal[j * n + i].real();
      t.r_im[i * t.count + j] = modal[j * n + i].imag();
    }
  t.w2.assign(t.count, 0.0);
  t.ball.assign(t.count, 0.0);
  t.ikc_re.assign(t.count, 0.0);
  t.ikc_im.assign(t.count, 0.0);
  t.kc_im.assign(t.count, 0.0);
  const double k0 = in.excitation.k0, c0 = in.damping, m2 = in.ball_mass, two_pi = 6.28318530717958647692;
  for (std::size_t j = 0; j < t.count; ++j) {
    const double w = two_pi * f[j];
    if (!(w > 0.0)) continue;
    t.w2[j] = w * w;
    t.ball[j] = 1.0 / (m2 * w * w);
    t.kc_im[j] = w * c0;
    const double d = 1.0 / (k0 * k0 + t.kc_im[j] * t.kc_im[j]);  // 1 / (k0 + i w c0), as linear_response
    t.ikc_re[j] = k0 * d;
    t.ikc_im[j] = -t.kc_im[j] * d;
  }
  return t;
}

// Scratch of one thread: per sensor, re and im over a range.
struct RangeScratch {
  std::vector<double> ab_re, ab_im, as_re, as_im, h_re, h_im, p_re, p_im;
  explicit RangeScratch(std::size_t ns)
      : ab_re(chunk_points),
        ab_im(chunk_points),
        as_re(ns * chunk_points),
        as_im(ns * chunk_points),
        h_re(ns * chunk_points),
        h_im(ns * chunk_points),
        p_re(chunk_points),
        p_im(chunk_points) {}
};

// The sensors' transfers H_s (B32-B33) at one position over the points [lo, lo + m), in the
// operations and order of linear_response_transfer (the same bits), laid out so that the compiler
// vectorises over the points; an AVX2 clone runs where the CPU has it (no FMA: the same bits).
__attribute__((target_clones("avx2", "default"))) void range_transfers(const PointTerms& t, std::size_t lo,
                                                                       std::size_t m, std::size_t modes, std::size_t ns,
                                                                       const double* cb, const double* cs, double rk,
                                                                       double k0, bool blocked, RangeScratch& w) {
  double* __restrict ab_re = w.ab_re.data();
  double* __restrict ab_im = w.ab_im.data();
  double* __restrict as_re = w.as_re.data();
  double* __restrict as_im = w.as_im.data();
  std::fill(ab_re, ab_re + m, 0.0);
  std::fill(ab_im, ab_im + m, 0.0);
  std::fill(as_re, as_re + ns * m, 0.0);
  std::fill(as_im, as_im + ns * m, 0.0);
  for (std::size_t i = 0; i < modes; ++i) {
    const double* __restrict rr = t.r_re.data() + i * t.count + lo;
    const double* __restrict ri = t.r_im.data() + i * t.count + lo;
    const double x = cb[i];
    for (std::size_t j = 0; j < m; ++j) {
      ab_re[j] += x * rr[j];
      ab_im[j] += x * ri[j];
    }
    for (std::size_t s = 0; s < ns; ++s) {
      const double y = cs[s * modes + i];
      double* __restrict sr = as_re + s * m;
      double* __restrict si = as_im + s * m;
      for (std::size_t j = 0; j < m; ++j) {
        sr[j] += y * rr[j];
        si[j] += y * ri[j];
      }
    }
  }
  // 1 / total, total = 1 / (k0 + i w c0) + alpha_b - 1 / (m2 w^2) + R k0 / (k0 + i w c0)  (B32),
  // times (k0 + i w c0) for a blocked force; kept in ab.
  const double* __restrict ikr = t.ikc_re.data() + lo;
  const double* __restrict iki = t.ikc_im.data() + lo;
  const double* __restrict ball = t.ball.data() + lo;
  const double* __restrict kci = t.kc_im.data() + lo;
  for (std::size_t j = 0; j < m; ++j) {
    double re = ikr[j] + ab_re[j], im = iki[j] + ab_im[j];
    re = re - ball[j];
    re = re + rk * ikr[j];
    im = im + rk * iki[j];
    if (blocked) {
      const double r2 = re * k0 - im * kci[j], i2 = re * kci[j] + im * k0;
      re = r2;
      im = i2;
    }
    const double d = 1.0 / (re * re + im * im);
    ab_re[j] = re * d;
    ab_im[j] = -im * d;
  }
  const double* __restrict w2 = t.w2.data() + lo;
  for (std::size_t s = 0; s < ns; ++s) {
    double* __restrict hr = w.h_re.data() + s * m;
    double* __restrict hi = w.h_im.data() + s * m;
    const double* __restrict sr = as_re + s * m;
    const double* __restrict si = as_im + s * m;
    for (std::size_t j = 0; j < m; ++j) {
      const double x = w2[j] * sr[j], y = w2[j] * si[j];  // (B33)
      hr[j] = x * ab_re[j] - y * ab_im[j];
      hi[j] = x * ab_im[j] + y * ab_re[j];
    }
  }
}

// exc H_1 conj(H_2) over the range, as std::complex evaluates (exc H_1) conj(H_2).
__attribute__((target_clones("avx2", "default"))) void range_product(const double* __restrict exc,
                                                                     const double* __restrict h1r,
                                                                     const double* __restrict h1i,
                                                                     const double* __restrict h2r,
                                                                     const double* __restrict h2i, std::size_t m,
                                                                     double* __restrict pr, double* __restrict pi) {
  for (std::size_t j = 0; j < m; ++j) {
    const double a = exc[j] * h1r[j], b = exc[j] * h1i[j];
    pr[j] = a * h2r[j] + b * h2i[j];
    pi[j] = b * h2r[j] - a * h2i[j];
  }
}

__attribute__((target_clones("avx2", "default"))) void range_add(double u, const double* __restrict x, std::size_t m,
                                                                 double* __restrict y) {
  for (std::size_t j = 0; j < m; ++j) y[j] += u * x[j];
}
}  // namespace

std::size_t linear_reference_steps(const LinearReferenceInput& in) {
  const FineGrid g = fine_grid(in);
  return point_ranges(g.nb, g.at.size()).size() + in.sensors.size() + (in.sensor_mean ? 1 : 0);
}

LinearReference linear_reference(const LinearReferenceInput& in, const std::function<void()>& step) {
  const FineGrid g = fine_grid(in);
  auto done = [&] {
    if (step) step();
  };
  const spectral::WelchPlan& welch = *in.welch;
  const ModalBeam& b = *in.beam;
  const ReferenceExcitation& ex = in.excitation;
  if (!(in.ball_mass > 0.0 && ex.k0 > 0.0 && in.damping >= 0.0))
    throw std::invalid_argument("linear_reference: need m2 > 0, k0 > 0, c0 >= 0");
  const PositionBlocks& pos = in.positions;
  const std::size_t blocks = pos.count(), n = pos.edges.back(), nf = g.nf, nb = g.nb, nc = g.at.size();
  const std::size_t ns = in.sensors.size(), pairs = ns * (ns + 1) / 2, modes = static_cast<std::size_t>(b.modes());
  const double weight_sum = position_weight_sum(pos);
  const std::vector<double> exc = reference_excitation(ex, g.f);
  const PointTerms t = point_terms(in, g.f);
  // Per block: the coefficients of its modal sums, phi_n(xi)^2 and phi_n(x_s) phi_n(xi), and R k0.
  std::vector<double> cb(blocks * modes), cs(blocks * ns * modes), rk(blocks), ps(ns * modes), pc(modes);
  for (std::size_t s = 0; s < ns; ++s) b.shapes(in.sensors[s], ps.data() + s * modes);
  for (std::size_t p = 0; p < blocks; ++p) {
    b.shapes(pos.position[p], pc.data());
    rk[p] = b.residual_flexibility(pos.position[p]) * ex.k0;
    for (std::size_t i = 0; i < modes; ++i) {
      cb[p * modes + i] = pc[i] * pc[i];
      for (std::size_t s = 0; s < ns; ++s) cs[(p * ns + s) * modes + i] = ps[s * modes + i] * pc[i];
    }
  }
  // The dof needs the blocks' smoothed cross-spectra only in the sums C_ab = sum_p u_ab(p) S_p
  // (B34b). Smoothing is linear: the products exc H_1 conj(H_2) are summed with u_ab(p) first and
  // each sum smoothed once, instead of smoothing every block's products.
  const spectral::WelchBlockTerms terms = spectral::welch_block_terms(welch, n, pos.edges);
  const std::size_t groups = terms.group_m.size();
  std::vector<std::vector<std::pair<std::size_t, double>>> block_terms(blocks);
  for (const auto& term : terms.terms) block_terms[term.block].emplace_back(term.group, term.u);
  std::vector<double> g_re(groups * pairs * nb, 0.0), g_im(groups * pairs * nb, 0.0);
  std::vector<std::vector<double>> psd(ns, std::vector<double>(nc, 0.0));
  const auto ranges = point_ranges(nb, nc);
  const auto nr = static_cast<std::ptrdiff_t>(ranges.size());
  const bool blocked = true;  // the excitation is the blocked force F0 (reference_excitation)
  // Ranges of points are independent, and within one the blocks are added in order: the same
  // result on any number of threads.
#pragma omp parallel
  {
    RangeScratch w(ns);
#pragma omp for schedule(static)
    for (std::ptrdiff_t rr = 0; rr < nr; ++rr) {
      const std::size_t lo =
          std::max<std::size_t>(ranges[static_cast<std::size_t>(rr)].first, 1);  // f = 0: no response
      const std::size_t hi = ranges[static_cast<std::size_t>(rr)].second, m = hi - lo;
      const bool band = hi <= nb;
      for (std::size_t p = 0; p < blocks; ++p) {
        if (!(pos.weight[p] > 0.0)) continue;  // a block no segment sees weighs nothing
        const double wp = pos.weight[p] / weight_sum;
        range_transfers(t, lo, m, modes, ns, cb.data() + p * modes, cs.data() + p * ns * modes, rk[p], ex.k0, blocked,
                        w);
        std::size_t q = 0;
        for (std::size_t s1 = 0; s1 < ns; ++s1)
          for (std::size_t s2 = s1; s2 < ns; ++s2, ++q) {
            if (!band && s2 != s1) continue;
            range_product(exc.data() + lo, w.h_re.data() + s1 * m, w.h_im.data() + s1 * m, w.h_re.data() + s2 * m,
                          w.h_im.data() + s2 * m, m, w.p_re.data(), w.p_im.data());
            if (s2 == s1) range_add(wp, w.p_re.data(), m, psd[s1].data() + lo);  // (B34), (B34a)
            if (!band) continue;
            for (const auto& [gi, u] : block_terms[p]) {
              range_add(u, w.p_re.data(), m, g_re.data() + (gi * pairs + q) * nb + lo);
              range_add(u, w.p_im.data(), m, g_im.data() + (gi * pairs + q) * nb + lo);
            }
          }
      }
#pragma omp critical(linear_reference_progress)
      done();
    }
  }
  // Each sum smoothed by the truncated Welch kernel at the bins (B34b).
  const SmoothingKernel sk = smoothing_kernel(welch, in.refine, g.half);
  std::vector<std::complex<double>> grouped(groups * pairs * nf);
  const auto planes = static_cast<std::ptrdiff_t>(groups * pairs);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t gq = 0; gq < planes; ++gq) {
    const double* xr = g_re.data() + static_cast<std::size_t>(gq) * nb;
    const double* xi = g_im.data() + static_cast<std::size_t>(gq) * nb;
    for (std::size_t k = 0; k < nf; ++k) {
      const std::size_t c = k * in.refine, j0 = c > sk.reach ? c - sk.reach : 0, j1 = std::min(g.half, c + sk.reach);
      double ar = 0.0, ai = 0.0;
      for (std::size_t j = j0; j <= j1; ++j) {
        ar += sk.taps[c + sk.reach - j] * xr[j];
        ai += sk.taps[c + sk.reach - j] * xi[j];
      }
      grouped[static_cast<std::size_t>(gq) * nf + k] = {ar / sk.norm[k], ai / sk.norm[k]};
    }
  }
  // Degrees of freedom of the ensemble mean per bin (B34b): each sensor from its own spectra, the
  // mean over sensors from all pairs (the sensors of one roll are correlated).
  std::vector<std::vector<double>> dof;
  for (std::size_t s = 0; s < ns; ++s) {
    const std::size_t q = s * ns - s * (s - 1) / 2;  // the (s, s) pair
    std::vector<std::complex<double>> own(groups * nf);
    for (std::size_t gi = 0; gi < groups; ++gi)
      std::copy_n(grouped.begin() + static_cast<std::ptrdiff_t>((gi * pairs + q) * nf), nf,
                  own.begin() + static_cast<std::ptrdiff_t>(gi * nf));
    dof.push_back(spectral::welch_group_dof(terms, 1, nf, own));
  }
  if (in.sensor_mean) dof.push_back(spectral::welch_group_dof(terms, ns, nf, grouped));
  return finish(in, g, psd, dof, done);
}

LinearReference linear_reference_plain(const LinearReferenceInput& in) {
  const FineGrid g = fine_grid(in);
  const spectral::WelchPlan& welch = *in.welch;
  const ReferenceExcitation& ex = in.excitation;
  const std::size_t refine = in.refine, nf = g.nf, half = g.half, nb = g.nb;
  const std::vector<double> exc = reference_excitation(ex, g.f);
  const PositionBlocks& pos = in.positions;
  const std::vector<std::size_t>& edges = pos.edges;
  const std::size_t n = edges.back(), ns = in.sensors.size(), pairs = ns * (ns + 1) / 2;
  // Above the band the PSD alone (it only aliases into the band): the plain modal sum.
  const std::vector<double> above(g.f.begin() + static_cast<std::ptrdiff_t>(nb), g.f.end());
  const std::vector<double> exc_above(exc.begin() + static_cast<std::ptrdiff_t>(nb), exc.end());
  std::vector<std::vector<double>> psd_above(ns);
  if (!above.empty())
    psd_above = linear_response_psd(*in.beam, in.ball_mass, ex.k0, in.damping, pos.position, in.sensors, above,
                                    exc_above, Excitation::blocked_force, pos.weight)
                    .sensor_psd;
  // In the band, per position block: the transfers H_s, their products exc H_1 conj(H_2) (the
  // pairs (s, s) give the PSD, position-weighted as linear_response_psd weighs them), and the
  // cross-spectra smoothed by the Welch kernel truncated at +-4 bins for the dof (B34b).
  const SmoothingKernel sk = smoothing_kernel(welch, refine, half);
  const std::vector<double> band(g.f.begin(), g.f.begin() + static_cast<std::ptrdiff_t>(nb));
  const double weight_sum = position_weight_sum(pos);
  std::vector<std::vector<double>> psd(ns, std::vector<double>(nb, 0.0));
  std::vector<std::complex<double>> cross((edges.size() - 1) * pairs * nf, 0.0);
  for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
    if (!(pos.weight[p] > 0.0)) continue;  // a block no segment sees weighs nothing
    const auto H = linear_response_transfer(*in.beam, in.ball_mass, ex.k0, in.damping, pos.position[p], in.sensors,
                                            band, Excitation::blocked_force);
    std::vector<std::vector<std::complex<double>>> product(pairs, std::vector<std::complex<double>>(nb));
    std::size_t q = 0;
    for (std::size_t s1 = 0; s1 < ns; ++s1)
      for (std::size_t s2 = s1; s2 < ns; ++s2, ++q)
        for (std::size_t j = 0; j < nb; ++j) product[q][j] = exc[j] * H[s1][j] * std::conj(H[s2][j]);
    const double wp = pos.weight[p] / weight_sum;
    for (std::size_t s = 0; s < ns; ++s) {
      const std::size_t qs = s * ns - s * (s - 1) / 2;  // the (s, s) pair
      for (std::size_t j = 0; j < nb; ++j) psd[s][j] += wp * product[qs][j].real();
    }
    for (std::size_t qq = 0; qq < pairs; ++qq)
      for (std::size_t k = 0; k < nf; ++k) {
        const std::size_t c = k * refine, j0 = c > sk.reach ? c - sk.reach : 0, j1 = std::min(half, c + sk.reach);
        std::complex<double> acc = 0.0;
        for (std::size_t j = j0; j <= j1; ++j) acc += sk.taps[c + sk.reach - j] * product[qq][j];
        cross[(p * pairs + qq) * nf + k] = acc / sk.norm[k];
      }
  }
  for (std::size_t s = 0; s < ns; ++s) psd[s].insert(psd[s].end(), psd_above[s].begin(), psd_above[s].end());
  // Degrees of freedom of the ensemble mean per bin (B34b).
  std::vector<std::vector<double>> dof;
  for (std::size_t s = 0; s < ns; ++s) {
    std::vector<std::complex<double>> own((edges.size() - 1) * nf);
    const std::size_t q = s * ns - s * (s - 1) / 2;
    for (std::size_t p = 0; p + 1 < edges.size(); ++p)
      for (std::size_t k = 0; k < nf; ++k) own[p * nf + k] = cross[(p * pairs + q) * nf + k];
    dof.push_back(spectral::welch_block_dof(welch, n, edges, 1, nf, own));
  }
  if (in.sensor_mean) dof.push_back(spectral::welch_block_dof(welch, n, edges, ns, nf, cross));
  return finish(in, g, psd, dof, [] {});
}

}  // namespace rollspec::beam
