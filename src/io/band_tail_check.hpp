#pragma once
// Whether K realisations suffice for the band intervals (kernels/spectral D-29): the /bands
// attributes tail_check (a sentence) and tail_check_realisations_needed (the K that Cochran's
// rule asks for in the worst row and band; 0: none), and one warning line from `run` naming
// that band when K falls short.
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/spectral/third_octave_bands.hpp"
#include "src/io/psd_result.hpp"

namespace rollspec::io {

class Hdf5Writer;

struct BandTailVerdict {
  std::string text;          // the attribute's sentence, and the warning's when short_of
  bool short_of = false;     // K is too few for the worst band
  std::uint64_t needed = 0;  // the K asked for there (0: no evidence of a tail, or not checked)
};

// The worst row and band of e.band_tail (rows x bands, bands: the result's bands).
BandTailVerdict band_tail_verdict(const PsdEnsemble& e, const std::vector<spectral::Band>& bands);

void write_band_tail_check(Hdf5Writer& w, const PsdEnsemble& e, const std::vector<spectral::Band>& bands);

}  // namespace rollspec::io
