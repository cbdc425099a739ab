#include "src/scenes/random_oscillator/random_oscillator.hpp"
#include "src/scenes/random_oscillator/random_oscillator_settings.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/scenes/study_welch.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>

#include "kernels/integrators/exact_oscillator_step.hpp"
#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/spectral/welch.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/psd_result.hpp"
#include "src/rng/philox_stream.hpp"

namespace rollspec::scenes {

using namespace study;

namespace {

struct Workspace {
  explicit Workspace(std::size_t n, std::size_t segment)
      : force(n), accel(n), u_phase(n / 2 + 1), u_amp(n / 2 + 1), scratch(n), welch(segment) {}
  std::vector<double> force, accel, u_phase, u_amp;
  spectral::SynthesisScratch scratch;
  spectral::WelchWorkspace welch;
};

class RandomOscillator final : public EnsembleScene {
 public:
  explicit RandomOscillator(const KeyReader& s) : o_(read_random_oscillator_settings(s)) {
    welch_ = std::make_unique<spectral::WelchPlan>(o_.welch);
    rows_ = std::make_unique<PsdRows>(std::vector<std::string>{"mass"}, false, welch_->frequencies(), o_.band_min,
                                      o_.band_max, 0);
    synth_ = std::make_unique<spectral::HarmonicSynthesiser>(o_.samples);
    df_ = o_.sample_rate / static_cast<double>(o_.samples);
    psd_at_harmonics_.resize(synth_->harmonics());
    for (std::size_t j = 0; j < psd_at_harmonics_.size(); ++j)
      psd_at_harmonics_[j] = o_.force_psd(df_ * static_cast<double>(j));
    half_amplitudes_ = spectral::synthesis_half_amplitudes(psd_at_harmonics_.data(), psd_at_harmonics_.size(), df_);
    omega_ = 2.0 * M_PI * o_.natural_frequency;
    step_ = integrators::ExactOscillatorStep::make(omega_, o_.damping_ratio, 1.0 / o_.sample_rate);
    // Phi^N, the free response over one period, for the periodic steady state.
    Eigen::Matrix2d phi;
    phi << step_.a00, step_.a01, step_.a10, step_.a11;
    Eigen::Matrix2d p = Eigen::Matrix2d::Identity(), b = phi;
    for (std::size_t e = o_.samples; e; e >>= 1, b = b * b)
      if (e & 1) p = p * b;
    periodic_inverse_ = (Eigen::Matrix2d::Identity() - p).inverse();
    for (int t = 0; t < ensemble::ensemble_threads(); ++t)
      workspaces_.push_back(std::make_unique<Workspace>(o_.samples, o_.welch.segment));
    add_stages(fixed_stages());  // after the members the descriptions name
  }

  std::vector<StagePlan> fixed_stages() const {
    return {
        {"texture", StageStatus::skipped, "the scene has no rough surface"},
        {"surface", StageStatus::skipped, "the scene has no contact"},
        {"stiffness_table", StageStatus::skipped, "the scene has no contact"},
        {"blocked_force", StageStatus::skipped, "the scene has no contact"},
        {"force", StageStatus::run,
         "synthesised per realisation from [force] (Philox streams force_phase, force_amplitude)"},
        {"dynamics", StageStatus::run, "exact first-order-hold oscillator step from the periodic steady state"},
        {"spectra", StageStatus::run, "Welch PSD of the acceleration, averaged over realisations"},
    };
  }

  std::size_t values_per_realisation() const override { return rows_->size(); }

  void run_realisation(std::uint64_t id, int thread, double* values) const override {
    Workspace& ws = *workspaces_[static_cast<std::size_t>(thread)];
    const std::size_t nh = synth_->harmonics();
    rng::PhiloxStream(o_.seed, id, rng::Stream::force_phase).uniform_open(ws.u_phase.data(), nh);
    rng::PhiloxStream(o_.seed, id, rng::Stream::force_amplitude).uniform_open(ws.u_amp.data(), nh);
    synth_->synthesise(half_amplitudes_.data(), o_.amplitudes, ws.u_phase.data(), ws.u_amp.data(), ws.force.data(),
                       ws.scratch);
    for (double& f : ws.force) f /= o_.mass;
    // Pass 1 from rest over one period gives the forced part r; the periodic start is (I - Phi^N)^-1 r.
    double q = 0.0, v = 0.0;
    for (std::size_t i = 0; i < o_.samples; ++i) step_.advance(q, v, ws.force[i], ws.force[(i + 1) % o_.samples]);
    const Eigen::Vector2d start = periodic_inverse_ * Eigen::Vector2d(q, v);
    q = start(0);
    v = start(1);
    const double c = 2.0 * o_.damping_ratio * omega_, k = omega_ * omega_;
    for (std::size_t i = 0; i < o_.samples; ++i) {
      ws.accel[i] = ws.force[i] - c * v - k * q;
      step_.advance(q, v, ws.force[i], ws.force[(i + 1) % o_.samples]);
    }
    welch_->psd(ws.accel.data(), o_.samples, rows_->row(values, 0), ws.welch);
    rows_->finish(values);
  }

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override {
    const io::PsdEnsemble e = rows_->welch_ensemble(sums, *welch_, o_.samples, o_.confidence);
    io::write_psd_result(w, e);

    std::vector<double> exact(e.frequency.size());
    for (std::size_t i = 0; i < exact.size(); ++i)
      exact[i] = random_oscillator_exact_psd(e.frequency[i], o_.force_psd(e.frequency[i]), o_.mass,
                                             o_.natural_frequency, o_.damping_ratio, o_.sample_rate);
    io::write_exact_reference(w, e, exact,
                              "exact acceleration PSD |H_a|^2 S_F of the sampled, first-order-hold driven oscillator");
    w.write("/oscillator/force_psd", {1}, &o_.level, "N^2/Hz", "flat force PSD level");
    w.attribute("/oscillator", "mass", o_.mass);
    w.attribute("/oscillator", "natural_frequency", o_.natural_frequency);
    w.attribute("/oscillator", "damping_ratio", o_.damping_ratio);
    w.attribute("/oscillator", "sample_rate", o_.sample_rate);
  }

 private:
  RandomOscillatorSettings o_;
  double df_ = 0.0, omega_ = 0.0;
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::unique_ptr<spectral::HarmonicSynthesiser> synth_;
  std::vector<double> psd_at_harmonics_, half_amplitudes_;
  integrators::ExactOscillatorStep step_{};
  Eigen::Matrix2d periodic_inverse_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace

std::unique_ptr<Scene> make_random_oscillator(const KeyReader& s) { return std::make_unique<RandomOscillator>(s); }

ResultShape random_oscillator_result_shape(const KeyReader& s) {
  const RandomOscillatorSettings o = read_random_oscillator_settings(s);
  return psd_result_shape({"mass"}, false, o.welch, o.band_min, o.band_max);
}

double random_oscillator_exact_psd(double f, double s_f, double mass, double natural_frequency, double damping_ratio,
                                   double sample_rate) {
  const double w = 2.0 * M_PI * f, wn = 2.0 * M_PI * natural_frequency;
  const double x = M_PI * f / sample_rate;
  const double hold = x == 0.0 ? 1.0 : std::sin(x) / x;
  const std::complex<double> restoring(wn * wn, 2.0 * damping_ratio * wn * w);
  const std::complex<double> h = 1.0 - hold * hold * restoring / (restoring - w * w);
  return std::norm(h) * s_f / (mass * mass);
}

}  // namespace rollspec::scenes
