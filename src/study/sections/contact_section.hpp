#pragma once
// [contact] (scene ball-on-beam): the contact law, its damping and loss of contact, the linearised
// law's blocked force and the filter on the roughness, read once; the checks across sections stay
// with the scene's settings (ball_on_beam_settings), named by the origins kept here.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct ContactSection {
  std::string law, loss, blocked_force, filter;  // as written
  double damping = 0.0, k0 = 0.0;
  KeyOrigin filter_origin;
  bool filter_set = false;  // written in the study or by --set (not the default)
  // The laws that read a stiffness table (table: the fitted curve; literal: seed 001 Eq. 7 from it).
  bool uses_stiffness_table() const { return law == "table" || law == "literal"; }

  static std::vector<KeySpec> keys();
  static ContactSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
