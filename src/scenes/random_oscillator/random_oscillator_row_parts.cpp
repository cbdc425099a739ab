// What scene `random-oscillator`'s registry row (scene_registry.cpp) names besides its class and keys: its memory
// model and the references a run cites.
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/random_oscillator/random_oscillator.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/random_oscillator_sections.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"

namespace rollspec::scenes {

std::vector<MemoryItem> random_oscillator_memory(const study::KeyReader& s, int threads) {
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

std::vector<std::string> random_oscillator_references(const study::KeyReader& s) {
  ReferenceIds ids = {"D-3", "D-18", "D-19"};
  add_references(ids, ensemble_spectra_references(s));
  return ids;
}

}  // namespace rollspec::scenes
