#pragma once
// [roughness] (scene ball-on-beam): the line texture's spacing (0: one sample per integration
// step) and its band limit, read once.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class BandLimit { output, step };

inline constexpr ChoiceTable<BandLimit, 2> kBandLimits{{
    {BandLimit::output, "output",
     "wavelengths shorter than v / (sample_rate / 2) dropped, an ideal anti-alias filter on the linear response; "
     "kernels/beam B40"},
    {BandLimit::step, "step", "up to the sampling's pi/dx: the response above sample_rate / 2 aliases into the bands"},
}};

struct RoughnessSection : DeclaredSection<RoughnessSection> {
  double spacing = 0.0;  // m; 0: derived from the step
  BandLimit band_limit = BandLimit::output;

  static SectionKeys<RoughnessSection> declare();
};

}  // namespace rollspec::study
