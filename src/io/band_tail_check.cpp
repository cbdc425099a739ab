#include "src/io/band_tail_check.hpp"

#include <cstdio>

#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"
#include "src/io/run_warning.hpp"

namespace rollspec::io {

BandTailVerdict band_tail_verdict(const PsdEnsemble& e, const std::vector<spectral::Band>& bands) {
  BandTailVerdict v;
  const std::uint64_t K = e.realisations;
  const std::size_t nb = bands.size();
  if (K < spectral::kMinRealisationsForInterval || nb == 0 || e.band_tail.size() != e.sensors.size() * nb) {
    v.text = "not checked: no band intervals";
    return v;
  }
  // The worst band: the largest K asked for, else the largest skewness of the band logs.
  std::size_t worst = e.band_tail.size();
  for (std::size_t i = 0; i < e.band_tail.size(); ++i) {
    const spectral::TailCheck& t = e.band_tail[i];
    if (!t.defined) continue;
    if (worst == e.band_tail.size() || t.needed > e.band_tail[worst].needed ||
        (t.needed == e.band_tail[worst].needed && t.skewness > e.band_tail[worst].skewness))
      worst = i;
  }
  if (worst == e.band_tail.size()) {
    v.text = "not checked: no band's logs scatter";
    return v;
  }
  const spectral::TailCheck& t = e.band_tail[worst];
  v.needed = t.needed;
  v.short_of = !t.enough(K);
  const std::string where = "the " + four_digits(bands[worst % nb].nominal) + " Hz band of " + e.sensors[worst / nb];
  const std::string stat = "skewness of the realisations' band logs G1 = " + four_digits(t.skewness) +
                           " (standard error se = " + four_digits(t.standard_error) + ")";
  const std::string rule = "Cochran's rule K >= 25 (G1 - 2 se)^2";
  if (!v.short_of)
    v.text = counted(K, "realisation") + " enough in every band by " + rule + " on the band logs; largest " + stat +
             " in " + where + " (kernels/spectral D-29)";
  else
    v.text = counted(K, "realisation") + " too few for " + where + ": " + stat +
             ", a tail heavier than the interval's laws, so its interval may under-cover; " + rule +
             " asks for K >= " + std::to_string(t.needed) + " (kernels/spectral D-29)";
  return v;
}

void write_band_tail_check(Hdf5Writer& w, const PsdEnsemble& e, const std::vector<spectral::Band>& bands) {
  const BandTailVerdict v = band_tail_verdict(e, bands);
  w.attribute("/bands", "tail_check", v.text);
  w.attribute("/bands", "tail_check_realisations_needed", static_cast<std::int64_t>(v.needed));
  if (v.short_of) warn(v.text);
}

}  // namespace rollspec::io
