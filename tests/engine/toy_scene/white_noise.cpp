#include "tests/engine/toy_scene/white_noise.hpp"

#include <cmath>
#include <string>

#include "kernels/spectral/welch.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/psd_result.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/scenes/study_welch.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/random_oscillator_sections.hpp"
#include "src/study/sections/section_keys.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::study {

SectionKeys<NoiseSection> NoiseSection::declare() {
  using T = NoiseSection;
  return SectionKeys<T>("noise").real("level", &T::level, "(m/s^2)^2/Hz", "one-sided PSD S of the white noise", "1e-4",
                                      above(0.0));
}
template struct DeclaredSection<NoiseSection>;

}  // namespace rollspec::study

namespace rollspec::scenes {

using namespace study;

namespace {

struct Workspace {
  Workspace(std::size_t n, std::size_t segment) : x(n), u1(n / 2), u2(n / 2), welch(segment) {}
  std::vector<double> x, u1, u2;
  spectral::WelchWorkspace welch;
};

class WhiteNoise final : public EnsembleScene {
 public:
  explicit WhiteNoise(const KeyReader& s)
      : seed_(StudySection::parse(s).seed),
        level_(NoiseSection::parse(s).level),
        signal_(RecordSignalSection::parse(s)),
        spectrum_(SpectrumSection::parse(s)) {
    if (static_cast<std::size_t>(spectrum_.segment) > signal_.samples)
      spectrum_.origin(spectrum_.segment)
          .refuse("is longer than one realisation's record (" + std::to_string(signal_.samples) + " samples)");
    welch_ = std::make_unique<spectral::WelchPlan>(study_welch_config(spectrum_, signal_.sample_rate));
    rows_ = std::make_unique<PsdRows>(std::vector<std::string>{"sensor"}, false, welch_->frequencies(),
                                      spectrum_.band_min, spectrum_.band_max, 0);
    for (int t = 0; t < ensemble::ensemble_threads(); ++t)
      workspaces_.push_back(std::make_unique<Workspace>(signal_.samples, static_cast<std::size_t>(spectrum_.segment)));
    add_stages({{"noise", StageStatus::run,
                 "white Gaussian noise per realisation (Philox streams force_phase, "
                 "force_amplitude, Box-Muller)"},
                {"spectra", StageStatus::run, "Welch PSD of the sensor, averaged over realisations"}});
  }

  std::size_t values_per_realisation() const override { return rows_->size(); }

  void run_realisation(std::uint64_t id, int thread, double* values) const override {
    Workspace& ws = *workspaces_[static_cast<std::size_t>(thread)];
    std::vector<double>&x = ws.x, &u1 = ws.u1, &u2 = ws.u2;
    const std::size_t half = u1.size();  // samples is even (RecordSignalSection)
    rng::PhiloxStream(seed_, id, rng::Stream::force_phase).uniform_open(u1.data(), half);
    rng::PhiloxStream(seed_, id, rng::Stream::force_amplitude).uniform_open(u2.data(), half);
    const double sigma = std::sqrt(level_ * signal_.sample_rate / 2.0);  // S = 2 sigma^2 / f_s, one-sided
    for (std::size_t i = 0; i < half; ++i) {
      const double r = sigma * std::sqrt(-2.0 * std::log(u1[i])), a = 2.0 * M_PI * u2[i];
      x[2 * i] = r * std::cos(a);
      x[2 * i + 1] = r * std::sin(a);
    }
    welch_->psd(x.data(), x.size(), rows_->row(values, 0), ws.welch);
    rows_->finish(values);
  }

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override {
    const io::PsdEnsemble e = rows_->welch_ensemble(sums, *welch_, signal_.samples, spectrum_.confidence);
    io::write_psd_result(w, e);
    const std::vector<double> exact(e.frequency.size(), level_);
    io::write_exact_reference(w, e, exact, "exact PSD of the white noise: its level");
  }

 private:
  std::uint64_t seed_;
  double level_;
  RecordSignalSection signal_;
  SpectrumSection spectrum_;
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace

std::vector<KeySpec> white_noise_keys() {
  std::vector<KeySpec> k = NoiseSection::keys();
  for (auto& t : RecordSignalSection::keys()) k.push_back(t);
  return k;
}

std::unique_ptr<Scene> make_white_noise(const KeyReader& s) { return std::make_unique<WhiteNoise>(s); }

}  // namespace rollspec::scenes
