// Texture kernel throughput, one thread: line textures of 2^16 and 2^20 samples and 512^2
// spectral (2D Fourier-filtered) and seed line-sum surfaces per second. The U(0,1) arrays are
// drawn before timing (the engine's Philox draws are not part of the kernel); generator set-up
// (PSD at the harmonics, inverse Abel, FFTW plans) is timed separately.
//
// Then issue 18 goal 5, texture synthesis against its floor, in the same run: for line textures of
// 2^12, 2^16, 2^20 and 2^22 samples, the time of one realisation (the generator's generate() with
// a reused SynthesisScratch: spectrum from the U(0,1) arrays, then the inverse FFT) against a bare
// FFTW c2r of the same length (the same FFTW_ESTIMATE plan on fftw_malloc buffers, the spectrum
// restored untimed before each call, only fftw_execute timed), the two timed call by call in turn
// so that a change of machine load reaches both; ratio = synthesis / c2r (goal <= 2).
// previous = the synthesis as it was (libm per harmonic, buffers per call), same c2r plan.
// Also the engine's two Philox draws per harmonic (not part of the kernel), for the whole cost.
//
// Compile with: cmake --build <build> --target bench_texture
// Sample run:   ./bench_texture [seconds_per_case]   -> CSV on stdout, then the goal table
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "kernels/spectral/fftw_handles.hpp"
#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/seed_surface.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/spectral_surface.hpp"
#include "src/rng/philox_stream.hpp"

using namespace rollspec::texture;
using Clock = std::chrono::steady_clock;

namespace {
std::vector<double> uniforms(std::mt19937_64& rng, std::size_t n) {
  std::vector<double> u(n);
  for (double& v : u) v = 1.0 - std::generate_canonical<double, 53>(rng);
  return u;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Runs f until at least `budget` seconds (and 3 calls) have passed; returns calls and seconds.
template <class F>
std::pair<long, double> run(F&& f, double budget) {
  long calls = 0;
  const auto t0 = Clock::now();
  double t = 0.0;
  do {
    f();
    ++calls;
    t = seconds_since(t0);
  } while (t < budget || calls < 3);
  return {calls, t};
}

// Median of per-call times (seconds) of f over >= `budget` seconds and >= 5 calls; `untimed` runs
// before each call outside the clock.
template <class F, class G>
double median_call(F&& f, G&& untimed, double budget) {
  std::vector<double> t;
  double total = 0.0;
  while (total < budget || t.size() < 5) {
    untimed();
    const auto t0 = Clock::now();
    f();
    t.push_back(seconds_since(t0));
    total += t.back();
  }
  std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

// The synthesis as it was before issue 18 (libm log, cos, sin per harmonic; amplitudes from the
// PSD and FFTW buffers per call; output copied), kept here to time against the tabulated path.
void previous_synthesis(const rollspec::spectral::HarmonicSynthesiser& s, fftw_plan_s* plan,
                        const std::vector<double>& psd, double dk, const double* up, const double* ua, double* out) {
  const std::size_t n = s.samples(), nh = s.harmonics();
  const rollspec::spectral::ComplexBuffer spec(nh);
  const rollspec::spectral::RealBuffer buf(n);
  spec[0][0] = spec[0][1] = spec[nh - 1][0] = spec[nh - 1][1] = 0.0;
  for (std::size_t j = 1; j + 1 < nh; ++j) {
    const double a = 0.5 * std::sqrt(2.0 * psd[j] * dk) * std::sqrt(-std::log(ua[j]));
    const double phi = 2.0 * M_PI * up[j];
    spec[j][0] = a * std::cos(phi);
    spec[j][1] = a * std::sin(phi);
  }
  fftw_execute_dft_c2r(plan, spec.data(), buf.data());
  std::copy(buf.data(), buf.data() + n, out);
}

// Medians of per-call times (seconds) of each of `timed`, called in turn (A, B, A, B, ...)
// for >= `budget` seconds in all and >= 9 rounds, so a change of machine load during the run
// reaches every column alike; `untimed[i]` runs before timed[i] outside the clock.
std::vector<double> interleaved_medians(const std::vector<std::function<void()>>& timed,
                                        const std::vector<std::function<void()>>& untimed, double budget) {
  std::vector<std::vector<double>> t(timed.size());
  double total = 0.0;
  while (total < budget || t[0].size() < 9) {  // 2^22: ~0.3 s a round
    for (std::size_t i = 0; i < timed.size(); ++i) {
      untimed[i]();
      const auto t0 = Clock::now();
      timed[i]();
      t[i].push_back(seconds_since(t0));
      total += t[i].back();
    }
  }
  std::vector<double> medians;
  for (auto& v : t) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    medians.push_back(v[v.size() / 2]);
  }
  return medians;
}

// Goal 5 table: per size, c2r floor, synthesis, ratio, the previous synthesis, and the Philox draws.
void synthesis_against_floor(double budget) {
  using namespace rollspec;
  std::printf("\n# issue 18 goal 5: line texture synthesis vs a bare FFTW c2r of the same length (median per call)\n");
  std::printf(
      "samples,c2r_us,synthesis_us,ratio,c2r_ns_per_sample,synthesis_ns_per_sample,previous_us,previous_ratio,"
      "philox_draws_us\n");
  const double dx = 1e-5;
  const SelfAffinePsd line(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 2e-3, M_PI / dx, RmsTarget::height, 1e-6});
  for (int p : {12, 16, 20, 22}) {
    const std::size_t n = std::size_t(1) << p, nh = n / 2 + 1;
    // Floor: the same kind of plan the synthesiser makes.
    spectral::ComplexBuffer spec(nh), saved(nh);
    spectral::RealBuffer real(n);
    std::mt19937_64 mt(7);
    std::normal_distribution<double> z;
    for (std::size_t j = 0; j < nh; ++j) saved[j][0] = z(mt), saved[j][1] = z(mt);
    const spectral::FftwPlan plan(
        [&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n), spec.data(), real.data(), FFTW_ESTIMATE); },
        "bench c2r");
    // Synthesis: one realisation into an aligned output, scratch reused (as the engine does).
    const LineTextureGenerator gen(line.to_psd(), LineTextureSpec{n, dx, 0, Amplitudes::rayleigh, false});
    std::vector<double> up(gen.harmonics()), ua(gen.harmonics());
    rng::PhiloxStream(1, 0, rng::Stream::roughness_phase).uniform_open(up.data(), up.size());
    rng::PhiloxStream(1, 0, rng::Stream::roughness_amplitude).uniform_open(ua.data(), ua.size());
    SynthesisScratch scratch = gen.make_scratch();
    spectral::RealBuffer out(n);
    const spectral::HarmonicSynthesiser old(n);
    // c2r and synthesis in turn, call by call (medians of each); the slow previous path after.
    const std::vector<double> m = interleaved_medians(
        {[&] { fftw_execute_dft_c2r(plan.get(), spec.data(), real.data()); },
         [&] { gen.generate(up.data(), ua.data(), out.data(), scratch); }},
        {[&] { std::memcpy(spec.data(), saved.data(), nh * sizeof(spectral::FftwComplex)); }, [] {}}, budget);
    const double c2r = m[0], synth = m[1];
    const double previous = median_call(
        [&] {
          previous_synthesis(old, plan.get(), gen.target_psd(), gen.fundamental(), up.data(), ua.data(), out.data());
        },
        [] {}, budget / 2);
    std::uint64_t id = 0;
    const double draws = median_call(
        [&] {
          rng::PhiloxStream(1, id, rng::Stream::roughness_phase).uniform_open(up.data(), up.size());
          rng::PhiloxStream(1, id, rng::Stream::roughness_amplitude).uniform_open(ua.data(), ua.size());
          ++id;
        },
        [] {}, budget / 4);
    std::printf("%zu,%.3f,%.3f,%.2f,%.3f,%.3f,%.3f,%.2f,%.3f\n", n, c2r * 1e6, synth * 1e6, synth / c2r,
                c2r * 1e9 / double(n), synth * 1e9 / double(n), previous * 1e6, previous / c2r, draws * 1e6);
    std::fflush(stdout);
  }
}

void row(const std::string& name, std::size_t samples, double setup_s, long calls, double seconds) {
  const double rate = static_cast<double>(calls) / seconds;
  std::printf("%s,%zu,%.6f,%ld,%.6f,%.3f,%.4e\n", name.c_str(), samples, setup_s, calls, seconds, rate,
              static_cast<double>(samples) * rate);
}
}  // namespace

int main(int argc, char** argv) {
  // `bench_texture --synthesis [budget]`: only the goal-5 table (bench/bench_goals.py reads it).
  const bool synthesis_only = argc > 1 && std::string(argv[1]) == "--synthesis";
  const int budget_arg = synthesis_only ? 2 : 1;
  const double budget = argc > budget_arg ? std::atof(argv[budget_arg]) : 2.0;
  if (synthesis_only) {
    synthesis_against_floor(budget);
    return 0;
  }
  std::mt19937_64 rng(1);
  std::printf("case,samples,setup_s,realisations,seconds,realisations_per_s,samples_per_s\n");

  const double dx = 1e-5;
  const SelfAffinePsd line(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / 2e-3, M_PI / dx, RmsTarget::height, 1e-6});
  for (std::size_t n : {std::size_t(1) << 16, std::size_t(1) << 20}) {
    auto t0 = Clock::now();
    const LineTextureGenerator gen(line.to_psd(), LineTextureSpec{n, dx, 0, Amplitudes::rayleigh, false});
    const double setup = seconds_since(t0);
    const auto up = uniforms(rng, gen.harmonics()), ua = uniforms(rng, gen.harmonics());
    std::vector<double> out(n);
    const auto [calls, secs] = run([&] { gen.generate(up.data(), ua.data(), out.data()); }, budget);
    row("line_rayleigh_2^" + std::to_string(n == (1u << 16) ? 16 : 20), n, setup, calls, secs);
  }

  const double d = 1e-6;
  const SelfAffinePsd surf(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (32.0 * d), M_PI / d, RmsTarget::height, 0.2e-6});
  {
    auto t0 = Clock::now();
    const SpectralSurfaceGenerator gen(surf.to_psd(),
                                       SpectralSurfaceSpec{512, 512, d, d, Amplitudes::rayleigh, 1.0, false, 100});
    const double setup = seconds_since(t0);
    const auto up = uniforms(rng, gen.modes()), ua = uniforms(rng, gen.modes());
    Surface s;
    const auto [calls, secs] = run([&] { gen.generate(up.data(), ua.data(), s); }, budget);
    row("spectral_surface_512x512", 512 * 512, setup, calls, secs);
  }
  {
    SeedSurfaceRequest rq;
    rq.nx = rq.ny = 512;
    rq.dx = rq.dy = d;
    rq.correlation_x = rq.correlation_y = 10.0 * d;
    rq.sigma = 0.2e-6;
    rq.max_box = 64;
    auto t0 = Clock::now();
    const SeedSurfaceGenerator gen(surf.to_psd(), rq);
    const double setup = seconds_since(t0);
    const auto u = uniforms(rng, gen.random_count());
    Surface s;
    const auto [calls, secs] = run([&] { gen.generate(u.data(), s); }, budget);
    row("seed_surface_512x512", 512 * 512, setup, calls, secs);
  }
  synthesis_against_floor(budget);
  return 0;
}
