#include "src/scenes/memory_terms.hpp"

#include <algorithm>
#include <cmath>

#include "src/io/number_text.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

using Item = MemoryItem;

std::string key_text(const char* section, const char* key, double value) {
  return std::string("[") + section + "] " + key + " = " + io::number_text(value);
}
std::string key_text(const char* section, const char* key, const std::string& value) {
  return std::string("[") + section + "] " + key + " = " + value;
}
std::string positions_text(const char* section, const std::vector<double>& positions) {
  std::string v;
  for (double x : positions) v += (v.empty() ? "" : ", ") + io::number_text(x);
  return key_text(section, "positions", v);
}

// Contact solves on an nx x ny grid: the padded (2nx x 2ny) half-space operator and its FFT
// buffers, about five complex arrays (measured: 77 MB peak at 512^2).
Item contact_grid(double nx, double ny) {
  return {16.0 * 4.0 * nx * ny * 5.0,
          {key_text("surface", "nx", nx), key_text("surface", "ny", ny)},
          "contact solver grid"};
}

// Isotropic surfaces kept for the output (count x ny x nx) plus the generator's complex FFT grid.
Item surfaces(const study::SurfaceSection& f) {
  const double nx = static_cast<double>(f.nx), ny = static_cast<double>(f.ny), count = static_cast<double>(f.count);
  return {8.0 * nx * ny * (count + 6.0),
          {key_text("surface", "nx", nx), key_text("surface", "ny", ny), key_text("surface", "count", count)},
          "isotropic surfaces"};
}

// The ensemble's own storage: one chunk's rows (chunk_size x values), the partial sums the pairwise
// tree keeps (at most log2 of the chunk count, and log2 of the chunk size while a chunk is added,
// each [sum, sum of squares]) and the copies of the final reduction. It no longer grows with the
// number of chunks (TreeAccumulator). Values per realisation: PSD and band rows of each output row.
// `sensors`: the scene's sensor key, if it has one.
Item chunk_sums(const study::StudySection& st, const study::EnsembleSection& en, const study::SpectrumSection& sp,
                double rows, std::vector<std::string> sensors) {
  const double nf = static_cast<double>(sp.segment) / 2.0 + 1.0;
  const double values = 2.0 * rows * (nf + 40.0) + 8.0;
  const double K = std::max(static_cast<double>(st.realisations), 1.0),
               C = std::max(static_cast<double>(en.chunk_size), 1.0);
  const double kept = std::log2(std::max(K / C, 1.0)) + std::log2(C) + 6.0;
  std::vector<std::string> keys = {key_text("ensemble", "chunk_size", C),
                                   key_text("spectrum", "segment", static_cast<double>(sp.segment))};
  for (auto& k : sensors) keys.push_back(std::move(k));
  return {8.0 * values * (C + 2.0 * kept), keys, "one chunk of realisations and the partial sums of the ensemble"};
}

}  // namespace rollspec::scenes
