#pragma once
// [equivalent_roughness] (scene ball-on-beam, filter = solver): the strips whose h_eq PSD is
// averaged, the line drawn from it and the stiffness correction, read once.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class EquivalentLine { synthesised, strip };
enum class EquivalentStiffness { strip, law };

inline constexpr ChoiceTable<EquivalentLine, 2> kEquivalentLines{{
    {EquivalentLine::synthesised, "synthesised", "a Philox line texture per realisation from the strip-mean h_eq PSD"},
    {EquivalentLine::strip, "strip",
     "h_eq of strip 0 itself along the ball's path, on the grid law = path uses: the point law on h_eq against law "
     "= path on the same strip; every realisation rolls over this one strip"},
}};
inline constexpr ChoiceTable<EquivalentStiffness, 2> kEquivalentStiffnesses{{
    {EquivalentStiffness::strip, "strip",
     "the point law stretched along the approach so that it carries the weight with the strips' mean contact "
     "stiffness dP/d delta at delta_eq, kernels/contact ER-7"},
    {EquivalentStiffness::law, "law", "the law's own stiffness; h_eq alone"},
}};

struct EquivalentRoughnessSection : DeclaredSection<EquivalentRoughnessSection> {
  long long strips = 0;
  EquivalentLine line = EquivalentLine::synthesised;
  EquivalentStiffness stiffness = EquivalentStiffness::strip;
  long long leave_out = -1;       // >= 0: the sub-table without this strip (D-30)
  double answer_tolerance = 0.0;  // contact ER-8; 0: every solve to [stiffness] tolerance (the reference)

  static SectionKeys<EquivalentRoughnessSection> declare();
  void finish();                                      // checks across its keys, once they are read
  static std::string leave_out_setting(long long i);  // "<section>.leave_out=i", a --set text
};

}  // namespace rollspec::study
