#pragma once
// A result's band levels against a measurement, band by band and all bands at once (design §7 "the
// verdict has two ends"; kernels/spectral D-22, D-26, D-31 to D-34). The model end carries the
// realisations' scatter and, for a rig with another surface, the contact table's own error twice (D-31);
// the measurement end carries its M rolls, its resolution and its noise floor (D-32, D-33). Bands near
// the noise floor leave the test and the level offset and are shown apart.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "kernels/spectral/level_offset.hpp"
#include "src/compare/combined_test.hpp"
#include "src/compare/measured_spectrum.hpp"
#include "src/io/band_levels.hpp"

namespace rollspec::compare {

enum class BandUse {
  test,         // in the combined test and the level offset
  noise_floor,  // within the margin of the noise recording's level (D-33a)
  floor_flat,   // no noise recording: flat at the measurement's lowest level while the model falls (D-33b)
};
const char* band_use_name(BandUse u);

struct BandRow {
  std::size_t band = 0;                                               // index in the result's bands
  double centre = 0.0, simulated = 0.0, measured = 0.0, delta = 0.0;  // dB; delta = simulated - measured
  double ci_lower = NAN, ci_upper = NAN, pred_lower = NAN, pred_upper = NAN;
  bool inside_ci = false, inside_prediction = false;
  BandUse use = BandUse::test;
  double noise = NAN;  // the noise recording's band level, dB (NaN: none)
};

struct VerdictOptions {
  double fmin = 0.0, fmax = INFINITY;
  double test_level = 0.05;
  bool same_surface = false;
  const MeasuredSpectrum* noise = nullptr;  // the rig at rest, through the same estimator
  double noise_margin_db = 10.0;            // D-33a: bands closer than this to the noise leave the test
  bool floor_check = true;                  // D-33b without a noise recording
  std::vector<double> model_psd;            // the row's mean PSD on the model's grid (the resolution check)
  double model_df = 0.0;                    // its bin width, Hz
};

struct Verdict {
  std::string question;       // what `inside` and the test answer
  double table_factor = 0.0;  // c of D-31 (0: same surface, or no random table)
  std::vector<BandRow> rows;
  CombinedTest test;
  std::optional<spectral::LevelOffset> offset;  // simulated - measured over the tested bands, dB (D-34)
  double rms_db = NAN;                          // rms of delta over the tested bands
  int inside = 0, judged = 0, tested = 0;
  std::vector<std::string> warnings;  // one line each: excluded bands, a likely unit slip, resolution, table
};

// Requires m.records > 0 for the prediction interval, the test and the offset; without it the question is
// whether each measured level lies inside the interval of the simulated mean. Throws data_error when the
// measurement covers none of the bands inside [fmin, fmax].
Verdict band_verdict(const io::BandLevels& b, const MeasuredSpectrum& m, const VerdictOptions& o);

}  // namespace rollspec::compare
