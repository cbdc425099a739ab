#include "kernels/texture/spectral_surface.hpp"

#include <fftw3.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/spectral/tabulated_math.hpp"

namespace rollspec::texture {

namespace {
void validate(const Psd& psd, const SpectralSurfaceSpec& s) {
  if (s.nx < 4 || s.ny < 4 || s.nx % 2 || s.ny % 2)
    throw std::invalid_argument("spectral surface: nx and ny must be even and >= 4 (got " + std::to_string(s.nx) +
                                " x " + std::to_string(s.ny) + ")");
  if (!(s.dx > 0.0) || !(s.dy > 0.0) || !std::isfinite(s.dx) || !std::isfinite(s.dy))
    throw std::invalid_argument("spectral surface: dx and dy must be positive and finite");
  if (!(s.anisotropy > 0.0) || !std::isfinite(s.anisotropy))
    throw std::invalid_argument("spectral surface: anisotropy ratio must be positive and finite");
  const double a = std::sqrt(s.anisotropy);
  if (!s.allow_truncation &&
      (psd.support_max / a > M_PI / s.dx * (1.0 + 1e-12) || psd.support_max * a > M_PI / s.dy * (1.0 + 1e-12)))
    throw UnresolvedPsd("spectral surface: the PSD (" + psd.description +
                            ") carries power up to k_max = " + std::to_string(psd.support_max) +
                            " rad/m, beyond the grid's pi/dx = " + std::to_string(M_PI / s.dx) +
                            ", pi/dy = " + std::to_string(M_PI / s.dy) +
                            " rad/m (with the anisotropy stretch); refine the grid or cut the PSD off",
                        psd.support_max);
}
}  // namespace

SpectralSurfaceGenerator::SpectralSurfaceGenerator(const Psd& psd, const SpectralSurfaceSpec& spec) : spec_(spec) {
  validate(psd, spec_);
  const std::size_t nh = spec_.nx / 2 + 1;
  const double dqx = 2.0 * M_PI / (static_cast<double>(spec_.nx) * spec_.dx);
  const double dqy = 2.0 * M_PI / (static_cast<double>(spec_.ny) * spec_.dy);
  const double a = std::sqrt(spec_.anisotropy);
  const double q_min = 0.5 * std::min(a * dqx, dqy / a);
  const double q_grid = std::hypot(a * M_PI / spec_.dx, M_PI / (a * spec_.dy));
  iso_ = std::make_unique<IsotropicPsd>(psd, q_min, 1e3 * q_grid, spec_.points_per_decade);
  const double width = std::sqrt(dqx * dqy);
  // Eq. 26a: a mode stands for the cell sx x sy around it (stretched axes, Eq. 27). Where that cell
  // is elongated (a strip: ny dy << nx dx) and near the origin, C_iso changes by orders of magnitude
  // across it and one radial mean of width sqrt(dqx dqy) overweights the long waves (a 0.6 mm wide
  // strip had 3x the rms of a square surface); there the mode takes the mean of Eq. 21 over
  // near-square sub-cells of side min(sx, sy). Square cells: one sub-cell, Eq. 21 as before.
  const double sx = a * dqx, sy = dqy / a, side = std::min(sx, sy);
  const auto nsx = static_cast<std::size_t>(std::max(1.0, std::round(sx / side)));
  const auto nsy = static_cast<std::size_t>(std::max(1.0, std::round(sy / side)));
  const double near = 4.0 * std::max(sx, sy);  // beyond it the cell spans < 1/8 rad: Eq. 21 holds
  c_.assign(modes(), 0.0);
  for (std::size_t iy = 0; iy < spec_.ny; ++iy) {
    if (iy == spec_.ny / 2) continue;  // Nyquist row
    const double qy =
        dqy * (iy < spec_.ny / 2 ? static_cast<double>(iy) : static_cast<double>(iy) - static_cast<double>(spec_.ny));
    for (std::size_t ix = 0; ix + 1 < nh; ++ix) {  // ix = nx/2: Nyquist column
      if (ix == 0 && iy == 0) continue;            // DC
      const double px = a * dqx * static_cast<double>(ix), py = qy / a;
      const double q = std::hypot(px, py);  // Eq. 27
      if (nsx * nsy == 1 || q >= near) {
        c_[iy * nh + ix] = iso_->cell_average(q, width);  // Eq. 21
        continue;
      }
      double sum = 0.0;  // Eq. 26a
      for (std::size_t jy = 0; jy < nsy; ++jy)
        for (std::size_t jx = 0; jx < nsx; ++jx) {
          const double ux = px + sx * ((static_cast<double>(jx) + 0.5) / static_cast<double>(nsx) - 0.5);
          const double uy = py + sy * ((static_cast<double>(jy) + 0.5) / static_cast<double>(nsy) - 0.5);
          sum += iso_->cell_average(std::hypot(ux, uy), side);
        }
      c_[iy * nh + ix] = sum / static_cast<double>(nsx * nsy);
    }
  }
  // |Z_q| of Eq. 26 before the Rayleigh factor: the same every realisation.
  const double base = std::sqrt(dqx * dqy) / (2.0 * M_PI);
  amp_.assign(modes(), 0.0);
  for (std::size_t i = 0; i < amp_.size(); ++i)
    if (c_[i] > 0.0) amp_[i] = base * std::sqrt(c_[i]);
  spectral::tabulated_math();
  const spectral::RealBuffer out(spec_.nx * spec_.ny);
  const spectral::ComplexBuffer in(modes());
  plan_ = spectral::FftwPlan(
      [&] {
        return fftw_plan_dft_c2r_2d(static_cast<int>(spec_.ny), static_cast<int>(spec_.nx), in.data(), out.data(),
                                    FFTW_ESTIMATE);
      },
      "spectral surface (2D c2r)");
}

double SpectralSurfaceGenerator::target_variance() const {
  const std::size_t nh = spec_.nx / 2 + 1;
  const double dqx = 2.0 * M_PI / (static_cast<double>(spec_.nx) * spec_.dx);
  const double dqy = 2.0 * M_PI / (static_cast<double>(spec_.ny) * spec_.dy);
  double v = 0.0;
  for (std::size_t iy = 0; iy < spec_.ny; ++iy)
    for (std::size_t ix = 0; ix < nh; ++ix) v += (ix == 0 ? 1.0 : 2.0) * c_[iy * nh + ix];  // +q and -q
  return v * dqx * dqy / (4.0 * M_PI * M_PI);
}

std::vector<std::complex<double>> SpectralSurfaceGenerator::coefficients(const double* u_phase,
                                                                         const double* u_amplitude) const {
  const std::size_t nh = spec_.nx / 2 + 1, ny = spec_.ny;
  const spectral::TabulatedMath& t = spectral::tabulated_math();
  const bool rayleigh = spec_.amplitudes == spectral::Amplitudes::rayleigh;
  std::vector<std::complex<double>> z(modes(), {0.0, 0.0});
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nh; ++ix) {
      const std::size_t i = iy * nh + ix;
      if (c_[i] <= 0.0) continue;
      if (ix == 0 && iy > ny / 2) continue;  // conjugate of (0, ny - iy), set below
      double amp = amp_[i];                  // Eq. 26; -ln u, cos and sin of 2 pi v by spectral D-24, D-25
      if (rayleigh) amp *= std::sqrt(spectral::neg_log_open(u_amplitude[i], t));
      double c, s;
      spectral::sincos_two_pi(u_phase[i], t, c, s);
      z[i] = {amp * c, amp * s};
    }
  for (std::size_t iy = 1; iy < ny / 2; ++iy)
    z[(ny - iy) * nh] = std::conj(z[iy * nh]);  // Z_{-q} = conj(Z_q) on qx = 0
  return z;
}

void SpectralSurfaceGenerator::generate(const double* u_phase, const double* u_amplitude, Surface& out) const {
  const std::vector<std::complex<double>> z = coefficients(u_phase, u_amplitude);
  const spectral::ComplexBuffer in(modes());
  const spectral::RealBuffer buf(spec_.nx * spec_.ny);
  for (std::size_t i = 0; i < z.size(); ++i) {
    in[i][0] = z[i].real();
    in[i][1] = z[i].imag();
  }
  // FFTW's c2r sums the implicit conjugates of 0 < ix < nx/2, which is exactly Eq. 26.
  fftw_execute_dft_c2r(plan_.get(), in.data(), buf.data());
  out = Surface(spec_.nx, spec_.ny, spec_.dx, spec_.dy);
  std::copy(buf.data(), buf.data() + spec_.nx * spec_.ny, out.heights.begin());
}

Surface spectral_surface_direct(const SpectralSurfaceGenerator& gen, const double* u_phase, const double* u_amplitude) {
  const SpectralSurfaceSpec& s = gen.spec();
  const std::vector<std::complex<double>> z = gen.coefficients(u_phase, u_amplitude);
  const std::size_t nh = s.nx / 2 + 1;
  Surface out(s.nx, s.ny, s.dx, s.dy);
  for (std::size_t y = 0; y < s.ny; ++y)
    for (std::size_t x = 0; x < s.nx; ++x) {
      double acc = 0.0;
      for (std::size_t iy = 0; iy < s.ny; ++iy)
        for (std::size_t ix = 0; ix < nh; ++ix) {
          const std::complex<double> c = z[iy * nh + ix];
          if (c == 0.0) continue;
          const double arg = 2.0 * M_PI *
                             (static_cast<double>(ix * x % s.nx) / static_cast<double>(s.nx) +
                              static_cast<double>(iy * y % s.ny) / static_cast<double>(s.ny));
          const double re = c.real() * std::cos(arg) - c.imag() * std::sin(arg);
          acc += (ix == 0 ? 1.0 : 2.0) * re;  // + its conjugate at -q for ix > 0
        }
      out.at(x, y) = acc;
    }
  return out;
}

}  // namespace rollspec::texture
