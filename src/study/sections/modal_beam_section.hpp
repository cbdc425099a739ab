#pragma once
// [beam] of scene ball-on-beam: the modal Euler-Bernoulli beam (kernels/beam modal_beam), read once.
#include <vector>

#include "kernels/beam/modal_beam.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

inline constexpr ChoiceTable<beam::Support, 2> kBeamSupports{{
    {beam::Support::clamped_clamped, "clamped-clamped", ""},
    {beam::Support::simply_supported, "simply-supported", ""},
}};

struct ModalBeamSection : DeclaredSection<ModalBeamSection> {
  beam::BeamProperties properties;
  beam::ModeSelection selection;
  beam::ModalDamping damping;
  bool static_correction = true;
  double poisson = 0.0;  // the contact modulus's, not the modal beam's

  static SectionKeys<ModalBeamSection> declare();
  // The modes. Refuses an effective length shorter than the span, modes = 0 without max_frequency,
  // and (at [beam] modes) a beam the kernel refuses.
  beam::ModalBeam modal_beam() const;
};

}  // namespace rollspec::study
