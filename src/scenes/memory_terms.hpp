#pragma once
// Terms of the scenes' memory models (memory_estimate.hpp) that several scenes share: a key as the
// message names it, the contact solver's grid, isotropic surfaces and the ensemble's own storage.
#include <string>
#include <vector>

#include "src/scenes/memory_estimate.hpp"

namespace rollspec::study {
struct StudySection;
struct EnsembleSection;
struct SpectrumSection;
struct SurfaceSection;
}  // namespace rollspec::study

namespace rollspec::scenes {

// "[section] key = value", the value as the typed section holds it.
std::string key_text(const char* section, const char* key, double value);
std::string key_text(const char* section, const char* key, const std::string& value);
std::string positions_text(const char* section, const std::vector<double>& positions);
// Contact solves on an nx x ny grid.
MemoryItem contact_grid(double nx, double ny);
// Isotropic surfaces kept for the output plus the generator's FFT grid.
MemoryItem surfaces(const study::SurfaceSection& f);
// One chunk of realisations and the ensemble's partial sums; `sensors`: the scene's sensor key, if any.
MemoryItem chunk_sums(const study::StudySection& st, const study::EnsembleSection& en, const study::SpectrumSection& sp,
                      double rows, std::vector<std::string> sensors);

}  // namespace rollspec::scenes
