// Scene `random-oscillator`'s registry row (scene.hpp SceneInfo): everything the engine asks of it.
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/random_oscillator/random_oscillator.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/random_oscillator_sections.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::scenes {

namespace {

std::vector<MemoryItem> memory(const study::KeyReader& s, int threads) {
  // Per thread: force, acceleration and the two uniform draws (3 n doubles); shared: the
  // synthesiser's FFT (measured: 0.91 GB peak at n = 1e7 on 2 threads).
  const auto signal = study::RecordSignalSection::parse(s);
  const double n = signal.sample_rate * signal.duration, t = threads;
  return {{8.0 * n * (3.0 * t + 5.0),
           {key_text("signal", "sample_rate", signal.sample_rate), key_text("signal", "duration", signal.duration)},
           "one realisation's record per thread"},
          chunk_sums(study::StudySection::parse(s), study::EnsembleSection::parse(s), study::SpectrumSection::parse(s),
                     1.0, {})};
}

std::vector<std::string> references(const study::KeyReader& s) {
  ReferenceIds ids = {"D-3", "D-18", "D-19"};
  add_references(ids, ensemble_spectra_references(s));
  return ids;
}

}  // namespace

SceneInfo random_oscillator_row() {
  return {"random-oscillator",
          "linear single-degree-of-freedom oscillator driven by a random force from a PSD; exact answer |H|^2 S_F",
          SceneKind::ensemble,
          SceneCommand::run,
          random_oscillator_keys,
          [](const study::KeyReader& s) { return make_random_oscillator(s); },
          random_oscillator_result_shape,
          random_oscillator_first_keys(),
          memory,
          nullptr,
          nullptr,
          nullptr,
          references};
}

}  // namespace rollspec::scenes
