// Equivalent-roughness stage benchmark (issue 19, `[contact] filter = solver`; kernels/contact
// equivalent_roughness.hpp, README ER-1 … ER-6). Prints CSV to stdout:
//   case,positions,seconds,seconds_per_position,iterations_per_position,note
//
//   small      the isotropic-PSD doctest's path: 12 cells per Hertz radius, 41² window, rms 1e-3 δ_H
//   seed002    a seed-002-like strip: 40 mm steel ball, E* = 115.4 GPa, H = 5 GPa, W = 2.58 N, on the
//              seed 002 rig texture (self-affine H = 0.2, roll-off 50 mm, cut-off 4 µm, rms 0.123 µm)
//              as an isotropic surface, strip 80 mm × 1.3 mm at 2 µm cells, path steps a/4 along
//              the centre line; wall seconds on OMP_NUM_THREADS threads (the solver's own threads,
//              or with ER_CHUNK the path's chunks, equivalent_roughness.hpp)
//
//   departure  uniform corrugation h = A cos(kx) at ka = 1 and 2: the fundamental of h_eq over
//              A sin(ka)/(ka) (1 = the linear-elastic limit ER-4) and the mean of h_eq over A, against
//              the amplitude A/δ_H (partial contact from A ≈ δ_H/… on) and the hardness H/p0
//              (22 cells per Hertz radius, ball on a cell centre; the 1e-3 row is the discretisation)
//   isotropic  the doctest's isotropic surface (8 cells per a, steps a/4, 2 surfaces, path y_c = 0) at
//              rms/δ_H = 1e-3 (linear) … 0.3 and H = p0, 0.5 p0 (at 0.6 δ_H crests beyond 2.5 a touch, BF-5): per
//              third-octave band, the PSD of h_eq over the PSD of the 1e-3 run on the same surfaces (dB,
//              amplitude-normalised: the departure from the linear limit free of sampling scatter), the 1e-3 run
//              against G_eq, and the mean contact area over the flat one
//
// Usage: [ER_STIFFNESS_TOL=1e-12] [ER_LOAD_TOL=1e-10] [ER_CELL=2e-6 (seed002 cell, m)] [ER_CHUNK=0 (positions per
// parallel chunk)] [ER_DUMP=file (CSV: position_m,approach_m,height_m)] bench_equivalent_roughness [small | departure |
// isotropic | seed002 [length_m] [window_half_width_in_a]]
#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "kernels/contact/equivalent_roughness.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/contact_filtered_psd.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/spectral_surface.hpp"

using namespace rollspec;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> uniforms(std::mt19937_64& rng, std::size_t n) {
  std::vector<double> u(n);
  for (double& v : u) v = 1.0 - std::generate_canonical<double, 53>(rng);
  return u;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Ball {
  double radius = 0.02, e_star = 115.4e9, load = 2.58;
  double hertz_approach() const { return std::pow(3.0 * load / (4.0 * e_star * std::sqrt(radius)), 2.0 / 3.0); }
  double hertz_radius() const { return std::sqrt(radius * hertz_approach()); }
};

void run(const char* name, const contact::Grid& strip, const std::vector<double>& heights, const contact::Grid& window,
         const Ball& b, std::size_t step, const contact::SolverOptions& opt, double load_tolerance, const char* note) {
  std::vector<double> x;
  const std::size_t margin = window.nx / 2 + 1;
  for (std::size_t ix = margin; ix + margin < strip.nx; ix += step) x.push_back(strip.x(ix));
  contact::ContactSolver solver(window, b.e_star);
  const auto t0 = std::chrono::steady_clock::now();
  contact::EquivalentRoughnessOptions path;
  path.load_tolerance = load_tolerance;
  path.chunk_positions = std::getenv("ER_CHUNK") ? static_cast<std::size_t>(std::atol(std::getenv("ER_CHUNK"))) : 0;
  const auto r =
      contact::equivalent_roughness(solver, strip, heights, b.radius, contact::BallShape::Sphere, x, b.load, opt, path);
  const double s = seconds_since(t0);
  double rms = 0.0, area = 0.0, plastic = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    rms += r.height[k] * r.height[k];
    area += r.contact_area[k];
    plastic += r.plastic_cells[k];
  }
  const double n = static_cast<double>(x.size());
  // position, δ_eq, h_eq per line (%.17g: old/new paths compared), a CSV standard readers load as it is;
  // the smooth approach, one number, on stderr
  if (const char* dump = std::getenv("ER_DUMP")) {
    if (FILE* f = std::fopen(dump, "w")) {
      std::fprintf(stderr, "%s: smooth_approach %.17g m\n", dump, r.smooth_approach);
      std::fprintf(f, "position_m,approach_m,height_m\n");
      for (std::size_t k = 0; k < x.size(); ++k)
        std::fprintf(f, "%.17g,%.17g,%.17g\n", x[k], r.approach[k], r.height[k]);
      std::fclose(f);
    }
  }
  std::printf(
      "%s,%zu,%.3f,%.5f,%.1f,%s; chunks of %zu positions; converged %d; rms h_eq %.4g m; mean contact area / flat "
      "%.3f; "
      "plastic cells per position %.1f\n",
      name, x.size(), s, s / n, r.iterations / n, note, path.chunk_positions, r.converged ? 1 : 0, std::sqrt(rms / n),
      area / n / r.smooth_contact_area, plastic / n);
}

// Least-squares h ≈ c0 + c cos(kx) + s sin(kx): returns {c0, sqrt(c² + s²)} (Eigen's QR).
std::pair<double, double> fit(const std::vector<double>& x, const std::vector<double>& h, double k) {
  Eigen::MatrixXd f(static_cast<Eigen::Index>(x.size()), 3);
  for (std::size_t i = 0; i < x.size(); ++i)
    f.row(static_cast<Eigen::Index>(i)) << 1.0, std::cos(k * x[i]), std::sin(k * x[i]);
  const Eigen::Vector3d c = f.colPivHouseholderQr().solve(Eigen::Map<const Eigen::VectorXd>(h.data(), f.rows()));
  return {c(0), std::hypot(c(1), c(2))};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "small";
  std::printf("case,positions,seconds,seconds_per_position,iterations_per_position,note\n");
  std::mt19937_64 rng(2002);
  // Options: the frozen-set stiffness CG tolerance (Newton's slope) and the load tolerance |P − W|/W.
  const double stiffness_tolerance =
      std::getenv("ER_STIFFNESS_TOL") ? std::atof(std::getenv("ER_STIFFNESS_TOL")) : 1e-12;
  const double load_tolerance = std::getenv("ER_LOAD_TOL") ? std::atof(std::getenv("ER_LOAD_TOL")) : 1e-10;
  if (which == "small") {
    Ball b;
    b.load = 4.0 / 3.0 * b.e_star * std::sqrt(b.radius) * std::pow(0.241e-6, 1.5);
    const double a = b.hertz_radius(), dx = a / 12.0;
    texture::SelfAffineSpec spec;
    spec.hurst = 0.8;
    spec.k_rolloff = 1.0 / a;
    spec.k_short = 6.0 / a;
    spec.rms = 1e-3 * b.hertz_approach();
    texture::SpectralSurfaceSpec sspec;
    sspec.nx = 2048;
    sspec.ny = 96;
    sspec.dx = sspec.dy = dx;
    const texture::SpectralSurfaceGenerator gen(texture::SelfAffinePsd(spec).to_psd(), sspec);
    texture::Surface s;
    const auto u1 = uniforms(rng, gen.modes()), u2 = uniforms(rng, gen.modes());
    gen.generate(u1.data(), u2.data(), s);
    const std::size_t half = 20;  // 40² window (1.67 a half-width): 80² products, no large prime factor
    contact::SolverOptions opt;
    opt.stiffness_tolerance = stiffness_tolerance;
    char note[120];
    std::snprintf(note, sizeof note, "elastic; stiffness tolerance %.0e; load tolerance %.0e", stiffness_tolerance,
                  load_tolerance);
    run("small", contact::Grid{sspec.nx, sspec.ny, dx, dx}, s.heights, contact::Grid{2 * half, 2 * half, dx, dx}, b, 3,
        opt, load_tolerance, note);
    return 0;
  }
  if (which == "isotropic") {
    Ball b;
    b.load = 4.0 / 3.0 * b.e_star * std::sqrt(b.radius) * std::pow(0.241e-6, 1.5);
    const double a = b.hertz_radius(), dx = a / 8.0, d_h = b.hertz_approach();
    const double p0 = 2.0 * b.e_star * a / (kPi * b.radius);
    texture::SelfAffineSpec spec;
    spec.hurst = 0.8;
    spec.k_rolloff = 1.0 / a;
    spec.k_short = 6.0 / a;
    spec.rms = 1.0;  // scaled below
    const texture::Psd g1 = texture::SelfAffinePsd(spec).to_psd();
    texture::SpectralSurfaceSpec sspec;
    sspec.nx = 4096;
    sspec.ny = 96;
    sspec.dx = sspec.dy = dx;
    const texture::SpectralSurfaceGenerator gen(g1, sspec);
    // Window 40² (half-width 2.5 a: rough crests outside 1.75 a touch at rms 0.6 δ_H).
    const contact::Grid strip{sspec.nx, sspec.ny, dx, dx}, window{40, 40, dx, dx};
    std::vector<double> x;
    for (std::size_t ix = 22; ix + 22 < strip.nx; ix += 2) x.push_back(strip.x(ix));
    spectral::WelchConfig cfg;
    cfg.sample_rate = 1.0 / (2.0 * dx);
    cfg.segment = 512;
    cfg.overlap = 256;
    const spectral::WelchPlan plan(cfg);
    spectral::WelchWorkspace ws(cfg.segment);
    const double dn = cfg.sample_rate / static_cast<double>(cfg.segment);
    std::vector<texture::Surface> surfaces(2);
    for (auto& s : surfaces) {
      const auto u1 = uniforms(rng, gen.modes()), u2 = uniforms(rng, gen.modes());
      gen.generate(u1.data(), u2.data(), s);
    }
    struct Run {
      double rms, hardness;
    };
    const std::vector<Run> runs = {{1e-3, 0.0}, {0.1, 0.0}, {0.3, 0.0}, {1e-3, 1.0}, {0.3, 1.0}, {1e-3, 0.5}};
    const auto bands = spectral::third_octave_bands(0.5 / (2.0 * kPi * a), 3.4 / (2.0 * kPi * a));
    std::vector<double> base;
    std::printf(
        "rms_over_delta_H,hardness_over_p0,mean_area_over_flat,min_area_over_flat,plastic_cells,band_ka:dB...\n");
    for (const Run& run : runs) {
      std::vector<double> mean(plan.n_freq(), 0.0), one(plan.n_freq());
      double area = 0.0, amin = 1e300, plastic = 0.0;
      std::size_t count = 0;
      for (const auto& s0 : surfaces) {
        std::vector<double> h(s0.heights);
        for (double& v : h) v *= run.rms * d_h / spec.rms;  // the generator's rms is 1 m: scale
        contact::SolverOptions opt;
        if (run.hardness > 0.0) opt.hardness = run.hardness * p0;
        contact::ContactSolver solver(window, b.e_star);
        contact::EquivalentRoughnessOptions po;
        po.chunk_positions = 256;
        const auto r = contact::equivalent_roughness(solver, strip, h, b.radius, contact::BallShape::Paraboloid, x,
                                                     b.load, opt, po);
        std::vector<double> hn(r.height);
        for (double& v : hn) v /= run.rms * d_h;  // per unit rms
        plan.psd(hn.data(), hn.size(), one.data(), ws);
        for (std::size_t j = 0; j < one.size(); ++j) mean[j] += one[j] / (2.0 * kPi);
        for (std::size_t k = 0; k < x.size(); ++k) {
          area += r.contact_area[k] / r.smooth_contact_area;
          amin = std::min(amin, r.contact_area[k] / r.smooth_contact_area);
          plastic += r.plastic_cells[k];
          ++count;
        }
      }
      for (double& v : mean) v /= static_cast<double>(surfaces.size());
      if (base.empty()) base = mean;
      std::printf("%.3g,%s,%.3f,%.3f,%.1f", run.rms, run.hardness > 0.0 ? std::to_string(run.hardness).c_str() : "inf",
                  area / static_cast<double>(count), amin, plastic / static_cast<double>(count));
      for (const auto& band : bands) {
        const double e = spectral::band_average(mean.data(), mean.size(), dn, band.lower, band.upper);
        const double r0 = spectral::band_average(base.data(), base.size(), dn, band.lower, band.upper);
        std::printf(",%.2f:%+.2f", 2.0 * kPi * band.centre * a, 10.0 * std::log10(e / r0));
      }
      if (&run == &runs.front()) {  // the linear run against G_eq (unit rms)
        std::vector<double> k(mean.size());
        for (std::size_t j = 0; j < k.size(); ++j)
          k[j] = 2.0 * kPi * dn * static_cast<double>(std::max<std::size_t>(j, 1));
        std::vector<double> t = texture::contact_filtered_psd_at(g1, a, k, spec.k_short);
        t[0] = 0.0;
        std::printf("  [vs G_eq:");
        for (const auto& band : bands)
          std::printf(" %.2f:%+.2f", 2.0 * kPi * band.centre * a,
                      10.0 * std::log10(spectral::band_average(mean.data(), mean.size(), dn, band.lower, band.upper) /
                                        spectral::band_average(t.data(), t.size(), dn, band.lower, band.upper)));
        std::printf("]");
      }
      std::printf("\n");
      std::fflush(stdout);
    }
    return 0;
  }
  if (which == "departure") {
    std::printf(
        "ka,amplitude_over_delta_H,hardness_over_p0,fundamental_over_linear,mean_over_amplitude,"
        "min_contact_area_over_flat,plastic_cells_per_position\n");
    Ball b;
    const double d_h = b.hertz_approach(), a = b.hertz_radius(), dx = a / 22.0;
    const double p0 = 2.0 * b.e_star * a / (kPi * b.radius);
    const contact::Grid window{99, 99, dx, dx};  // half-width 2.2 a, odd: ball on a cell centre
    for (double ka : {1.0, 2.0})
      for (double hard : {0.0, 1.0, 0.5})
        for (double amp : {1e-3, 0.1, 0.3, 0.6, 1.0}) {
          const double k = ka / a;
          const double wavelength = 2.0 * kPi / k / dx;
          const std::size_t step = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(wavelength / 16.0)));
          const std::size_t count = 20;
          const contact::Grid strip{2 * window.nx + step * count, window.ny + 40, dx, dx};
          std::vector<double> h(strip.size());
          for (std::size_t iy = 0; iy < strip.ny; ++iy)
            for (std::size_t ix = 0; ix < strip.nx; ++ix) h[iy * strip.nx + ix] = amp * d_h * std::cos(k * strip.x(ix));
          std::vector<double> x(count);
          for (std::size_t i = 0; i < count; ++i) x[i] = strip.x(window.nx + i * step);
          contact::SolverOptions opt;
          if (hard > 0.0) opt.hardness = hard * p0;
          contact::ContactSolver solver(window, b.e_star);
          const auto r =
              contact::equivalent_roughness(solver, strip, h, b.radius, contact::BallShape::Sphere, x, b.load, opt);
          // Fundamental and mean by least squares on 1, cos, sin over the 20 positions (1.25 wavelengths).
          const auto [mean_fit, fundamental] = fit(x, r.height, k);
          double amin = 1e300, plastic = 0.0;
          for (std::size_t i = 0; i < count; ++i) {
            amin = std::min(amin, r.contact_area[i] / r.smooth_contact_area);
            plastic += r.plastic_cells[i];
          }
          std::printf("%.1f,%.3g,%s,%.4f,%.4f,%.3f,%.1f%s\n", ka, amp,
                      hard > 0.0 ? std::to_string(hard).c_str() : "inf", fundamental / (amp * d_h * std::sin(ka) / ka),
                      mean_fit / (amp * d_h), amin, plastic / static_cast<double>(count),
                      r.converged ? "" : " (not converged)");
          std::fflush(stdout);
        }
    return 0;
  }
  // seed002
  Ball b;
  const double length = argc > 2 ? std::atof(argv[2]) : 0.08;
  const double span = argc > 3 ? std::atof(argv[3]) : 2.0;
  const double dx = std::getenv("ER_CELL") ? std::atof(std::getenv("ER_CELL")) : 2e-6, a = b.hertz_radius();
  texture::SelfAffineSpec spec;
  spec.hurst = 0.2;
  spec.k_rolloff = 2.0 * kPi / 50e-3;
  spec.k_short = 2.0 * kPi / 4e-6;
  spec.rms = 0.123e-6;
  texture::SpectralSurfaceSpec sspec;
  sspec.nx = 2 * static_cast<std::size_t>(std::lround(0.5 * length / dx));
  sspec.ny = 2 * static_cast<std::size_t>(std::lround(0.5 * 1.3e-3 / dx));
  sspec.allow_truncation = dx > 2e-6;  // coarser cells drop the roughness below two cells
  sspec.dx = sspec.dy = dx;
  const auto tg = std::chrono::steady_clock::now();
  const texture::SpectralSurfaceGenerator gen(texture::SelfAffinePsd(spec).to_psd(), sspec);
  texture::Surface s;
  {
    const auto u1 = uniforms(rng, gen.modes()), u2 = uniforms(rng, gen.modes());
    gen.generate(u1.data(), u2.data(), s);
  }
  std::fprintf(stderr, "surface %zu x %zu generated in %.1f s\n", sspec.nx, sspec.ny, seconds_since(tg));
  // Window: at least 2·span·a wide, a multiple of 16 cells (FFT-friendly products).
  const std::size_t w = 16 * static_cast<std::size_t>(std::ceil(2.0 * span * a / dx / 16.0));
  contact::SolverOptions opt;
  opt.hardness = 5e9;
  opt.stiffness_tolerance = stiffness_tolerance;
  const std::size_t step = static_cast<std::size_t>(std::floor(0.25 * a / dx));
  char note[200];
  std::snprintf(note, sizeof note,
                "%zu x %zu strip, %zu^2 window, step %zu cells, a = %.1f um, stiffness tol %.0e, load tol %.0e",
                sspec.nx, sspec.ny, w, step, a * 1e6, stiffness_tolerance, load_tolerance);
  run("seed002", contact::Grid{sspec.nx, sspec.ny, dx, dx}, s.heights, contact::Grid{w, w, dx, dx}, b, step, opt,
      load_tolerance, note);
  return 0;
}
