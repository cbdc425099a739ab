#include "src/study/sections/equivalent_roughness_section.hpp"

#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> EquivalentRoughnessSection::keys() {
  return {
      integer_key("equivalent_roughness", "strips",
                  "filter = solver: rough strips (surface realisations 0..strips-1) whose h_eq PSD is averaged; the "
                  "strip grid is the blocked force's ([blocked_force] strip_length, window, step, segment)",
                  std::string("2"), 1, 1024),
      choice_key("equivalent_roughness", "line",
                 "filter = solver: synthesised (a Philox line texture per realisation from the strip-mean h_eq PSD) "
                 "or strip (h_eq of strip 0 itself along the ball's path, on the grid law = path uses: the point law "
                 "on h_eq against law = path on the same strip; every realisation rolls over this one strip)",
                 std::string("synthesised"), {"synthesised", "strip"}),
      choice_key("equivalent_roughness", "stiffness",
                 "filter = solver: strip (the point law stretched along the approach so that it carries the weight "
                 "with the strips' mean contact stiffness dP/d delta at delta_eq, kernels/contact ER-7) or law (the "
                 "law's own stiffness; h_eq alone)",
                 std::string("strip"), {"strip", "law"}),
      integer_key("equivalent_roughness", "leave_out",
                  "filter = solver: strip index (0 .. strips - 1) left out of the table's mean PSD and stiffness, from "
                  "the cached table without a new solve: a leave-one-out sub-table for the jackknife of the table's "
                  "own error ([stiffness] table_error = jackknife; kernels/spectral/README.md D-30); -1: none",
                  std::string("-1"), -1, 1023),
  };
}

EquivalentRoughnessSection EquivalentRoughnessSection::parse(const KeyReader& s) {
  EquivalentRoughnessSection p;
  p.strips = s.integer("equivalent_roughness.strips");
  p.line = s.text("equivalent_roughness.line");
  p.stiffness = s.text("equivalent_roughness.stiffness");
  p.line_origin = {s.where("equivalent_roughness.line")};
  p.leave_out = s.integer("equivalent_roughness.leave_out");
  p.leave_out_origin = {s.where("equivalent_roughness.leave_out")};
  if (p.leave_out >= p.strips)
    p.leave_out_origin.refuse("leaves out a strip the table does not have; allowed: -1 .. " +
                              std::to_string(p.strips - 1) +
                              " ([equivalent_roughness] strips = " + std::to_string(p.strips) + ")");
  return p;
}

}  // namespace rollspec::study
