#include "src/study/sections/blocked_force_section.hpp"

#include <limits>
#include <string>

#include "src/study/key_reader.hpp"

namespace rollspec::study {

std::vector<KeySpec> BlockedForceSection::keys() {
  return {
      real_key("blocked_force", "strip_length", "m",
               "length of the rough strip the ball slides along; 0: four Welch segments of positions plus the window",
               std::string("0"), 0.0, std::numeric_limits<double>::infinity()),
      integer_key("blocked_force", "window",
                  "cells of the contact solver's square window (8 or more); 0: derived so that the window holds every "
                  "cell the ball can touch, from the contact radius and the texture rms",
                  std::string("0"), 0, 4096),
      integer_key("blocked_force", "step",
                  "path step in cells; 0: a third of the contact radius (at most speed / sample_rate)",
                  std::string("0"), 0, 1000),
      integer_key(
          "blocked_force", "segment",
          "Welch segment (positions, 16 or more) of the F0 PSD along the path; 0: four times the F0 correlation "
          "length (2 pi x the contact radius, or the self-affine roll-off wavelength if longer)",
          std::string("0"), 0, 1 << 20),
      real_key("blocked_force", "answer_tolerance", "",
               "[contact] blocked_force = solver: 0, the reference path: the exhaustive load search, every position "
               "solved to [stiffness] tolerance on every path until the mean force meets the load; > 0 (e.g. 1e-3): "
               "the path's solves to this tolerance, stopped within 1e-2 of the load and put on it to first order "
               "along the stiffness (kernels/contact BF-8; about half the CPU on the seed 002 rig), each F0's "
               "estimated error kept in the table (force_error)",
               std::string("0"), 0.0, 0.1),
      integer_key("blocked_force", "leave_out",
                  "[contact] blocked_force = solver: Welch segment (0 .. segments - 1) of F0 along the path left out "
                  "of the table's PSD, from the cached table without a new solve: a leave-one-out sub-table for the "
                  "jackknife of the table's own error ([stiffness] table_error = jackknife; kernels/spectral/README.md "
                  "D-30d); -1: none",
                  std::string("-1"), -1, 1 << 20),
  };
}

BlockedForceSection BlockedForceSection::parse(const KeyReader& s) {
  BlockedForceSection b;
  b.strip_length = s.real("blocked_force.strip_length");
  b.window = s.integer("blocked_force.window");
  b.step = s.integer("blocked_force.step");
  b.segment = s.integer("blocked_force.segment");
  b.strip_length_origin = {s.where("blocked_force.strip_length")};
  b.window_origin = {s.where("blocked_force.window")};
  b.segment_origin = {s.where("blocked_force.segment")};
  b.answer_tolerance = s.real("blocked_force.answer_tolerance");
  b.leave_out = s.integer("blocked_force.leave_out");
  b.leave_out_origin = {s.where("blocked_force.leave_out")};
  return b;
}

}  // namespace rollspec::study
