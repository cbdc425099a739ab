// Ball-on-beam work-precision and per-realisation cost (issue 5), README "Benchmark".
//
// Compile with: cmake --build <build> --target bench_beam
// Sample run:   bench_beam > beam_work_precision.csv
// Description:  a seed-002-like rig (clamped–clamped 6 x 50 mm steel, span 0.39 m in l_eff = 0.42 m,
//   10 modes up to 10 kHz, 40 mm steel ball at 1 m/s, Hertz contact with c = 100 N s/m, roughness
//   synthesised from an exponential-correlation PSD). Error = max over third-octave bands
//   100 Hz – 5 kHz of |10 log10(L / L_ref)| of the sensor acceleration PSD (Welch, mean over the
//   5 sensors), against a converged reference. Prints CSV blocks (lines starting '#' name them).
#include <Random123/philox.h>
#include <Random123/uniform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "kernels/beam/dopri5_reference.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/linear_response.hpp"
#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/spectral/third_octave_bands.hpp"
#include "kernels/spectral/welch.hpp"

using namespace rollspec;
using namespace rollspec::beam;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double two_pi = 6.28318530717958647692;

BallOnBeamModel rig(double speed, double sample_rate) {
  BeamProperties p;
  p.length = 0.39;
  p.effective_length = 0.42;
  BallOnBeamModel m{ModalBeam(p, {0, 10000.0}, {0.02, {}}), Ball{}, ContactLaw{}, Traverse{}, sample_rate, {}};
  m.contact.kind = ContactLawKind::hertz;
  m.contact.damping = 100.0;
  m.traverse = {0.005, 0.385, speed, 0.0};
  m.sensors = {0.05, 0.13, 0.195, 0.26, 0.33};
  return m;
}

// Roughness h(x) by D-3 from G(k) = sigma^2 (2/pi) kc / (kc^2 + k^2), Philox-keyed phases.
struct RoughnessSource {
  std::size_t n = 1 << 16;
  double dx = 1e-5, sigma, kc = 5000.0;
  std::vector<double> psd;
  spectral::HarmonicSynthesiser synth{n};
  // k_cut > 0: no roughness above k_cut (band-limited input).
  explicit RoughnessSource(double rms, double k_cut = 0.0) : sigma(rms) {
    const double dk = two_pi / (static_cast<double>(n) * dx);
    for (std::size_t j = 0; j <= n / 2; ++j) {
      const double k = static_cast<double>(j) * dk;
      const bool pass = !(k_cut > 0.0) || k <= k_cut;
      psd.push_back(pass ? sigma * sigma * 2.0 / 3.14159265358979 * kc / (kc * kc + k * k) : 0.0);
    }
  }
  UniformSamples realise(unsigned long id, std::vector<double>& u) const {
    u.resize(n / 2 + 1);
    r123::Philox4x64 rng;
    r123::Philox4x64::key_type key = {{2026ul, id}};
    for (std::size_t j = 0; j < u.size(); ++j) {
      r123::Philox4x64::ctr_type c = {{j, 0, 0, 0}};
      u[j] = r123::u01<double>(rng(c, key)[0]);
    }
    UniformSamples s;
    s.origin = 0.0;
    s.step = dx;
    s.values.resize(n);
    synth.synthesise(psd.data(), two_pi / (static_cast<double>(n) * dx), spectral::Amplitudes::deterministic, u.data(),
                     nullptr, s.values.data());
    s.values.resize(static_cast<std::size_t>(0.40 / dx));
    return s;
  }
};

// Mean over sensors of the Welch PSD, then third-octave band levels 100 Hz - 5 kHz.
std::vector<double> band_levels(const BallOnBeamResult& r, const spectral::WelchPlan& plan,
                                spectral::WelchWorkspace& ws) {
  std::vector<double> mean(plan.n_freq(), 0.0), p(plan.n_freq());
  for (const auto& a : r.sensor_acceleration) {
    plan.psd(a.data(), a.size(), p.data(), ws);
    for (std::size_t k = 0; k < p.size(); ++k) mean[k] += p[k] / static_cast<double>(r.sensor_acceleration.size());
  }
  std::vector<double> out;
  for (const auto& b :
       spectral::third_octave_bands(100.0 / std::pow(10.0, 0.05) * 1.0001, 5000.0 * std::pow(10.0, 0.05) * 0.9999))
    out.push_back(spectral::band_average(mean.data(), mean.size(), plan.frequency_step(), b.lower, b.upper));
  return out;
}

double max_db_error(const std::vector<double>& a, const std::vector<double>& ref) {
  double e = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) e = std::max(e, std::abs(10.0 * std::log10(a[i] / ref[i])));
  return e;
}

template <class F>
double seconds(F&& f, int repeats) {
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string only = argc > 1 ? argv[1] : "";
  auto want = [&](const char* name) { return only.empty() || only == name; };
  // Optional argument: work, work_bandlimited, realisation, step, ensemble, linear_mc.
  const double fs = 12800.0;
  BallOnBeamModel m = rig(1.0, fs);
  spectral::WelchConfig wc;
  wc.sample_rate = fs;
  wc.segment = 1024;
  wc.overlap = 512;
  const spectral::WelchPlan plan(wc);
  spectral::WelchWorkspace ws(wc.segment);
  const RoughnessSource src(0.02e-6);  // 20 nm rms: near-linear (no loss of contact), see loss_share
  // The same roughness with nothing above 10 kHz at 1 m/s (k = 2 pi 1e4 rad/m): shows how much of
  // the error at coarse steps is aliasing of roughness content above the step's Nyquist frequency.
  const RoughnessSource src_bl(0.02e-6, two_pi * 1e4);
  std::vector<double> u;
  Realisation r;
  r.roughness = src.realise(1, u);

  // 1. Work-precision: one realisation, reference = exact-step at dt = 0.31 us (256 substeps).
  for (const RoughnessSource* rs : {&src, &src_bl}) {
    if (!want(rs == &src ? "work" : "work_bandlimited")) continue;
    r.roughness = rs->realise(1, u);
    std::printf("# roughness: %s\n", rs == &src ? "full band (to k = pi/dx)" : "band-limited to 10 kHz at 1 m/s");
    const BallOnBeamResult ref_es = ExactStepIntegrator(m, 256, 1e-13, 20'000'000).run(r);
    const std::vector<double> ref = band_levels(ref_es, plan, ws);
    ReferenceTolerances tight;
    tight.rtol = 1e-11;
    tight.atol_displacement = 1e-18;
    const BallOnBeamResult ref_dp = simulate_dopri5(m, r, tight);
    std::printf(
        "# work_precision: seed-002-like rig, %d modes (<= 10 kHz), Hertz, 1 m/s, %zu samples at %.0f Hz; "
        "reference exact-step 256 substeps; DOPRI5 rtol 1e-11 vs reference: %.2e dB; loss share %.4f\n",
        m.beam.modes(), ref_es.samples(), fs, max_db_error(band_levels(ref_dp, plan, ws), ref),
        ref_es.loss_of_contact_share);
    std::printf("method,parameter,value,dt_s,steps,rejected,time_s,max_band_error_db\n");
    for (ForceHold hold : {ForceHold::linear, ForceHold::quadratic})
      for (int s : {1, 2, 4, 8, 16, 32, 64}) {
        ExactStepOptions o;
        o.substeps = s;
        o.hold = hold;
        const ExactStepIntegrator integ(m, o);
        BallOnBeamResult res;
        const double t = seconds([&] { integ.run(r, res); }, 3);
        std::printf("%s,substeps,%d,%.4e,%ld,0,%.5f,%.3e\n",
                    hold == ForceHold::linear ? "exact_step" : "exact_step_quadratic", s, integ.step(), res.steps, t,
                    max_db_error(band_levels(res, plan, ws), ref));
      }
    for (double rtol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9}) {
      ReferenceTolerances tol;
      tol.rtol = rtol;
      tol.atol_displacement = rtol * 1e-7;  // displacements are ~1e-7 m
      BallOnBeamResult res;
      const double t = seconds([&] { res = simulate_dopri5(m, r, tol); }, 1);
      std::printf("dopri5,rtol,%.0e,,%ld,%ld,%.5f,%.3e\n", rtol, res.steps, res.rejected_steps, t,
                  max_db_error(band_levels(res, plan, ws), ref));
    }
  }

  // 2. Time per realisation, seed-002-like rig at 1 m/s: roughness synthesis (2^16-point FFT),
  //    exact-step integration, Welch PSDs of 5 sensors (one core; plan made once).
  if (want("realisation")) {
    std::printf("# per_realisation: one core, best of 5 after warm-up\n");
    std::printf("hold,substeps,dt_s,synthesis_ms,integration_ms,welch_ms,total_ms,realisations_per_s\n");
    for (auto [hold, s] : std::vector<std::pair<ForceHold, int>>{{ForceHold::linear, 2},
                                                                 {ForceHold::linear, 4},
                                                                 {ForceHold::linear, 8},
                                                                 {ForceHold::linear, 16},
                                                                 {ForceHold::quadratic, 2},
                                                                 {ForceHold::quadratic, 4}}) {
      ExactStepOptions o;
      o.substeps = s;
      o.hold = hold;
      const ExactStepIntegrator integ(m, o);
      BallOnBeamResult res;
      Realisation rr;
      unsigned long id = 10;
      const double ts = seconds([&] { rr.roughness = src.realise(id++, u); }, 5);
      const double ti = seconds([&] { integ.run(rr, res); }, 5);
      std::vector<double> lv;
      const double tw = seconds([&] { lv = band_levels(res, plan, ws); }, 5);
      const double tot = ts + ti + tw;
      std::printf("%s,%d,%.4e,%.3f,%.3f,%.3f,%.3f,%.1f\n", hold == ForceHold::linear ? "linear" : "quadratic", s,
                  integ.step(), 1e3 * ts, 1e3 * ti, 1e3 * tw, 1e3 * tot, 1.0 / tot);
    }
  }

  // 2b. The exact step as run() takes it (B26a: reordered, four modes per SIMD lane group) against
  //     run_reference() (the step as B23-B26 write it), interleaved in one run: seed-002 rig at
  //     25.6 kHz, 4 substeps, quadratic hold, Hertz and linearised (blocked force F0 = W + k0 h) laws.
  if (want("step")) {
    std::printf("# step: run() vs run_reference(), one core, best of 7 interleaved\n");
    std::printf("law,steps,reference_ms,run_ms,reference_over_run\n");
    for (const bool lin : {false, true}) {
      BallOnBeamModel sm = rig(1.0, 25600.0);
      if (lin) {
        sm.contact.kind = ContactLawKind::linearised;
        sm.contact.k0 = 6.8e6;
      }
      ExactStepOptions o;
      o.substeps = 4;
      o.hold = ForceHold::quadratic;
      const ExactStepIntegrator integ(sm, o);
      Realisation rr;
      rr.roughness = src.realise(7, u);
      if (lin) {  // F0(t) = W + k0 h(x_start + v t) on the line's own samples (D-11)
        const double v = sm.traverse.speed, x0 = sm.traverse.x_start, dx = rr.roughness.step;
        const auto first = static_cast<std::size_t>(std::ceil(x0 / dx));
        rr.blocked_force.origin = (static_cast<double>(first) * dx - x0) / v;
        rr.blocked_force.step = dx / v;
        for (std::size_t i = first; i < rr.roughness.values.size(); ++i)
          rr.blocked_force.values.push_back(sm.ball.mass * sm.ball.gravity + sm.contact.k0 * rr.roughness.values[i]);
        rr.roughness = UniformSamples{};
      }
      BallOnBeamResult res;
      double tr = 1e30, tf = 1e30;
      for (int i = 0; i < 7; ++i) {
        tr = std::min(tr, seconds([&] { integ.run_reference(rr, res); }, 1));
        tf = std::min(tf, seconds([&] { integ.run(rr, res); }, 1));
      }
      std::printf("%s,%ld,%.3f,%.3f,%.2f\n", lin ? "linearised" : "hertz", integ.steps(), 1e3 * tr, 1e3 * tf, tr / tf);
    }
  }

  // 3. Small ensemble (near-linear regime): exact-step (4, 8, 16 substeps) vs DOPRI5 (rtol 1e-9)
  //    band levels of the ensemble mean over 8 realisations.
  if (want("ensemble")) {
    ReferenceTolerances tol;
    tol.rtol = 1e-9;
    tol.atol_displacement = 1e-16;
    const int nr = 8;
    const std::vector<int> subs = {4, 8, 16, -2, -4};  // negative: quadratic hold
    std::vector<std::vector<double>> a(subs.size());
    std::vector<double> b;
    double loss = 0.0;
    for (int i = 0; i < nr; ++i) {
      Realisation rr;
      rr.roughness = src.realise(100 + static_cast<unsigned long>(i), u);
      const auto lb = band_levels(simulate_dopri5(m, rr, tol), plan, ws);
      if (b.empty()) b.assign(lb.size(), 0.0);
      for (std::size_t k = 0; k < lb.size(); ++k) b[k] += lb[k] / nr;
      for (std::size_t si = 0; si < subs.size(); ++si) {
        ExactStepOptions o;
        o.substeps = std::abs(subs[si]);
        o.hold = subs[si] < 0 ? ForceHold::quadratic : ForceHold::linear;
        const BallOnBeamResult x = ExactStepIntegrator(m, o).run(rr);
        loss = std::max(loss, x.loss_of_contact_share);
        const auto la = band_levels(x, plan, ws);
        if (a[si].empty()) a[si].assign(la.size(), 0.0);
        for (std::size_t k = 0; k < la.size(); ++k) a[si][k] += la[k] / nr;
      }
    }
    std::printf("# ensemble: %d realisations, mean band levels 100 Hz - 5 kHz, exact-step vs DOPRI5 rtol 1e-9\n", nr);
    std::printf("hold,substeps,dt_s,realisations,max_loss_share,max_band_difference_db\n");
    for (std::size_t si = 0; si < subs.size(); ++si)
      std::printf("%s,%d,%.4e,%d,%.4f,%.3e\n", subs[si] < 0 ? "quadratic" : "linear", std::abs(subs[si]),
                  1.0 / (fs * std::abs(subs[si])), nr, loss, max_db_error(a[si], b));
  }
  // 4. Linearised model (roughness through k0, c0, no tension clamp): Monte-Carlo mean of the
  //    Welch PSD (25 realisations x 5 sensors) against the frequency-domain solution (B31-B34)
  //    averaged over 200 ball positions; share of bins 100 Hz - 5 kHz inside the chi-square 95 %
  //    interval of the MC mean (per sensor: nu = 25 x Welch equivalent dof).
  if (want("linear_mc"))
    for (double vv : {1.0, 0.2}) {
      // 25.6 kHz output so that the sensor signals (modes and roughness to 10 kHz) do not alias.
      BallOnBeamModel lm = rig(vv, 2.0 * fs);
      spectral::WelchConfig lwc = wc;
      lwc.sample_rate = 2.0 * fs;
      lwc.segment = 2 * wc.segment;
      lwc.overlap = 2 * wc.overlap;
      const spectral::WelchPlan lplan(lwc);
      spectral::WelchWorkspace lws(lwc.segment);
      lm.contact.kind = ContactLawKind::linearised;
      lm.contact.k0 = 6.8e6;
      lm.contact.damping = 100.0;
      lm.contact.allow_tension = true;
      const RoughnessSource lin_src(0.1e-6, two_pi * 1e4 / vv);  // nothing above 10 kHz in time
      ExactStepOptions o;
      o.substeps = 4;
      o.hold = ForceHold::quadratic;
      const ExactStepIntegrator integ(lm, o);
      const int nr = 25;
      std::vector<std::vector<double>> mean(lm.sensors.size(), std::vector<double>(lplan.n_freq(), 0.0));
      std::vector<double> p(lplan.n_freq());
      for (int i = 0; i < nr; ++i) {
        Realisation rr;
        rr.roughness = lin_src.realise(500 + static_cast<unsigned long>(i), u);
        const BallOnBeamResult x = integ.run(rr);
        for (std::size_t sidx = 0; sidx < lm.sensors.size(); ++sidx) {
          lplan.psd(x.sensor_acceleration[sidx].data(), x.samples(), p.data(), lws);
          for (std::size_t k = 0; k < p.size(); ++k) mean[sidx][k] += p[k] / nr;
        }
      }
      // Roughness PSD in time at 1 m/s (D-2): G_t(f) = G(k) 2 pi / v, k = 2 pi f / v.
      const std::vector<double> freqs = lplan.frequencies();
      std::vector<double> gt(freqs.size());
      for (std::size_t k = 0; k < freqs.size(); ++k) {
        const double kk = two_pi * freqs[k] / lm.traverse.speed;
        const double g = kk <= two_pi * 1e4 / vv ? lin_src.sigma * lin_src.sigma * 2.0 / 3.14159265358979 * lin_src.kc /
                                                       (lin_src.kc * lin_src.kc + kk * kk)
                                                 : 0.0;
        gt[k] = g * two_pi / lm.traverse.speed;
      }
      std::vector<double> xi;
      for (int j = 0; j < 200; ++j)
        xi.push_back(lm.traverse.x_start + (lm.traverse.x_end - lm.traverse.x_start) * (j + 0.5) / 200.0);
      // The linearised law (D-11) with roughness: h enters through k0 only (its damper sees
      // w1' - w2', not h'), i.e. a blocked force F0 = k0 h.
      std::vector<double> gf(gt.size());
      for (std::size_t k = 0; k < gt.size(); ++k) gf[k] = lm.contact.k0 * lm.contact.k0 * gt[k];
      const LinearResponse fd = linear_response_psd(lm.beam, lm.ball.mass, lm.contact.k0, lm.contact.damping, xi,
                                                    lm.sensors, freqs, gf, Excitation::blocked_force);
      // Expected Welch estimate of a stationary process with the FD spectrum: the FD PSD convolved
      // with the normalised Hann spectral window |W(nu)|^2 (fine grid df/16, +-8 bins).
      std::vector<std::vector<double>> fdw(lm.sensors.size(), std::vector<double>(freqs.size(), 0.0));
      {
        const std::vector<double>& win = lplan.window();
        const double df = lplan.frequency_step();
        const int sub = 16, half = 8 * sub;
        std::vector<double> kern(2 * half + 1);
        double ksum = 0.0;
        for (int j = -half; j <= half; ++j) {
          std::complex<double> wsum = 0.0;
          const double nu = j * df / sub;
          for (std::size_t i = 0; i < win.size(); ++i)
            wsum += win[i] * std::polar(1.0, -two_pi * nu * static_cast<double>(i) / lwc.sample_rate);
          kern[j + half] = std::norm(wsum);
          ksum += kern[j + half];
        }
        for (double& kv : kern) kv /= ksum;
        std::vector<double> ff, gg;
        for (std::size_t k = 0; k < freqs.size(); ++k) {
          if (freqs[k] < 50.0 || freqs[k] > 5200.0) continue;
          for (int j = -half; j <= half; ++j) {
            const double f = freqs[k] + j * df / sub;
            const double kk = two_pi * f / lm.traverse.speed;
            ff.push_back(f);
            gg.push_back(lm.contact.k0 * lm.contact.k0 * lin_src.sigma * lin_src.sigma * 2.0 / 3.14159265358979 *
                         lin_src.kc / (lin_src.kc * lin_src.kc + kk * kk) * two_pi / lm.traverse.speed);
          }
        }
        const LinearResponse fine = linear_response_psd(lm.beam, lm.ball.mass, lm.contact.k0, lm.contact.damping, xi,
                                                        lm.sensors, ff, gg, Excitation::blocked_force);
        std::size_t pos = 0;
        for (std::size_t k = 0; k < freqs.size(); ++k) {
          if (freqs[k] < 50.0 || freqs[k] > 5200.0) continue;
          for (std::size_t sidx = 0; sidx < lm.sensors.size(); ++sidx)
            for (int j = 0; j <= 2 * half; ++j) fdw[sidx][k] += kern[j] * fine.sensor_psd[sidx][pos + j];
          pos += 2 * half + 1;
        }
      }
      const double dof = nr * lplan.equivalent_dof(output_samples(lm));
      const spectral::IntervalFactors ci = spectral::chi_square_interval(dof);
      std::printf(
          "# linear_mc: speed %.1f m/s, %d realisations, quadratic hold 4 substeps, dof per sensor %.1f, interval "
          "%.3f..%.3f\n",
          vv, nr, dof, ci.lower, ci.upper);
      std::printf(
          "sensor,bins,inside_share_fd,median_ratio_fd_db,inside_share_fd_windowed,median_ratio_fd_windowed_db\n");
      for (std::size_t sidx = 0; sidx < lm.sensors.size(); ++sidx) {
        int bins = 0, inside = 0, inside_w = 0;
        std::vector<double> ratio, ratio_w;
        for (std::size_t k = 0; k < freqs.size(); ++k) {
          if (freqs[k] < 100.0 || freqs[k] > 5000.0) continue;
          ++bins;
          const double est = mean[sidx][k], truth = fd.sensor_psd[sidx][k], truth_w = fdw[sidx][k];
          if (truth >= est * ci.lower && truth <= est * ci.upper) ++inside;
          if (truth_w >= est * ci.lower && truth_w <= est * ci.upper) ++inside_w;
          ratio.push_back(10.0 * std::log10(est / truth));
          ratio_w.push_back(10.0 * std::log10(est / truth_w));
        }
        auto median = [](std::vector<double> v) {
          std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
          return v[v.size() / 2];
        };
        std::printf("%.3f,%d,%.3f,%.3f,%.3f,%.3f\n", lm.sensors[sidx], bins, static_cast<double>(inside) / bins,
                    median(ratio), static_cast<double>(inside_w) / bins, median(ratio_w));
      }
    }
  return 0;
}
