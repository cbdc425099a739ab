#include "src/study/sections/equivalent_roughness_section.hpp"

#include <string>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<EquivalentRoughnessSection> EquivalentRoughnessSection::declare() {
  using T = EquivalentRoughnessSection;
  return SectionKeys<T>("equivalent_roughness")
      .integer("strips", &T::strips,
               "filter = solver: rough strips (surface realisations 0..strips-1) whose h_eq PSD is averaged; the "
               "strip grid is the blocked force's ([blocked_force] strip_length, window, step, segment)",
               "2", 1, 1024)
      .choice("line", &T::line, "filter = solver", EquivalentLine::synthesised, kEquivalentLines)
      .choice("stiffness", &T::stiffness, "filter = solver", EquivalentStiffness::strip, kEquivalentStiffnesses)
      .integer("leave_out", &T::leave_out,
               "filter = solver: strip index (0 .. strips - 1) left out of the table's mean PSD and stiffness, "
               "from the cached table without a new solve: a leave-one-out sub-table for the jackknife of the "
               "table's own error ([stiffness] table_error = jackknife; kernels/spectral/README.md D-30); -1: none",
               "-1", -1, 1023)
      .real("answer_tolerance", &T::answer_tolerance, "",
            "filter = solver: > 0, each position's solve stops at this tolerance and every 16th position is solved "
            "again from it to [stiffness] tolerance: h_eq's error measured there (kernels/contact ER-8), carried to "
            "the bands of its PSD; the result records each band's estimated error "
            "(/contact/equivalent_roughness_band_error_db) and run warns above 0.1 dB. 0, the reference path: "
            "every solve to [stiffness] tolerance",
            "0", within(0.0, 0.01));
}
template struct DeclaredSection<EquivalentRoughnessSection>;

std::string EquivalentRoughnessSection::leave_out_setting(long long i) {
  return declared().full_name(&EquivalentRoughnessSection::leave_out) + "=" + std::to_string(i);
}

void EquivalentRoughnessSection::finish() {
  if (leave_out >= strips)
    origin(leave_out).refuse("leaves out a strip the table does not have; allowed: -1 .. " +
                             std::to_string(strips - 1) +
                             " ([equivalent_roughness] strips = " + std::to_string(strips) + ")");
}

}  // namespace rollspec::study
