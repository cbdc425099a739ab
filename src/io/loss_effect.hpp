#pragma once
// What loss of contact moves (kernels/spectral D-35): a law that assumes a closed contact (law =
// linearised) lost contact; the same realisations are run again with a contact that never opens
// ([contact] loss = closed: the linear law in tension too), and each row's band levels are compared
// pair by pair. A band is moved when the shift exceeds both its own interval's half width (it would
// change a verdict) and the pairs' own uncertainty (t_{K-1} standard errors).
#include <cstddef>
#include <string>
#include <vector>

namespace rollspec::io {

struct PsdEnsemble;

struct LossEffect {
  bool measured = false;
  std::vector<double> shift_db;       // rows x bands: level as run minus level with a closed contact
  std::vector<double> shift_se_db;    // its standard error from the pairs
  std::vector<double> half_width_db;  // the band's own interval half width (D-21), dB
  std::size_t moved = 0, judged = 0;  // row-bands moved, row-bands with an interval
  double worst_db = 0.0;              // the largest shift of a moved band (or of any band if none moved)
  std::string worst_band;             // "sensor_mean, 800 Hz"
};

// From the two runs' spectra (the same rows and bands) and, per band value, the sums over realisations
// of x_open x_closed (`products`, rows x bands); K realisations, confidence `level`.
LossEffect loss_effect(const PsdEnsemble& open, const PsdEnsemble& closed, const std::vector<double>& products,
                       double level);

// The run's warning (a moved band) or note (none moved): what loss of contact moves, by how much, the
// threshold, and the key that changes it.
std::string loss_effect_sentence(double share, const LossEffect& e, bool& warning);

}  // namespace rollspec::io
