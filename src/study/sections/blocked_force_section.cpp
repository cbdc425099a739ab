#include "src/study/sections/blocked_force_section.hpp"

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

SectionKeys<BlockedForceSection> BlockedForceSection::declare() {
  using T = BlockedForceSection;
  return SectionKeys<T>("blocked_force")
      .real("strip_length", &T::strip_length, "m",
            "length of the rough strip the ball slides along; 0: four Welch segments of positions plus the window", "0",
            at_least(0.0))
      .integer("window", &T::window,
               "cells of the contact solver's square window (8 or more); 0: derived so that the window holds "
               "every cell the ball can touch, from the contact radius and the texture rms",
               "0", 0, 4096)
      .integer("step", &T::step, "path step in cells; 0: a third of the contact radius (at most speed / sample_rate)",
               "0", 0, 1000)
      .integer("segment", &T::segment,
               "Welch segment (positions, 16 or more) of the F0 PSD along the path; 0: four times the F0 "
               "correlation length (2 pi x the contact radius, or the self-affine roll-off wavelength if longer)",
               "0", 0, 1 << 20)
      .real("answer_tolerance", &T::answer_tolerance, "",
            "[contact] blocked_force = solver: > 0 (the default 1e-3): one path's solves to this tolerance, put "
            "on the load to first order, and every 16th position solved "
            "again to the full tolerance (finer while k0's estimated error is above 0.1 %): k0 from those checks, "
            "F0's error measured there (kernels/contact BF-8, BF-9; its speed and accuracy against the exhaustive "
            "search: the benchmarks page). The result records each band's estimated F0 error and k0's "
            "(/contact/blocked_force_band_error_db, @blocked_force_k0_error); run warns above 0.1 dB or 1 %. 0, the "
            "reference path: the exhaustive load search, every position solved to [stiffness] tolerance on every "
            "path until the mean force meets the load",
            "1e-3", within(0.0, 0.1))
      .integer("leave_out", &T::leave_out,
               "[contact] blocked_force = solver: Welch segment (0 .. segments - 1) of F0 along the path left out "
               "of the table's PSD, from the cached table without a new solve: a leave-one-out sub-table for the "
               "jackknife of the table's own error ([stiffness] table_error = jackknife; "
               "kernels/spectral/README.md D-30d); -1: none",
               "-1", -1, 1 << 20);
}
template struct DeclaredSection<BlockedForceSection>;

std::string BlockedForceSection::leave_out_setting(long long i) {
  return declared().full_name(&BlockedForceSection::leave_out) + "=" + std::to_string(i);
}

}  // namespace rollspec::study
