#include "src/study/sections/equivalent_roughness_section.hpp"

#include <string>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> EquivalentRoughnessSection::keys() {
  return {
      integer_key("equivalent_roughness", "strips",
                  "filter = solver: rough strips (surface realisations 0..strips-1) whose h_eq PSD is averaged; the "
                  "strip grid is the blocked force's ([blocked_force] strip_length, window, step, segment)",
                  std::string("2"), 1, 1024),
      choice_key("equivalent_roughness", "line", "filter = solver", EquivalentLine::synthesised, kEquivalentLines),
      choice_key("equivalent_roughness", "stiffness", "filter = solver", EquivalentStiffness::strip,
                 kEquivalentStiffnesses),
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
  p.line = read_choice(s, "equivalent_roughness.line", kEquivalentLines);
  p.stiffness = read_choice(s, "equivalent_roughness.stiffness", kEquivalentStiffnesses);
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
