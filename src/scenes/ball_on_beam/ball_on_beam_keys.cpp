// Study keys of scene `ball-on-beam` and the modal beam they describe (ball_on_beam.hpp).
#include <limits>
#include <string>

#include "kernels/beam/modal_beam.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam.hpp"
#include "src/scenes/stiffness/stiffness_scene.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/equivalent_roughness_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/output_section.hpp"
#include "src/study/sections/path_table_section.hpp"
#include "src/study/sections/roughness_section.hpp"
#include "src/study/sections/sensors_section.hpp"
#include "src/study/sections/signal_section.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> ball_on_beam_keys() {
  // [beam] and [ball] first, then the scene's other keys, in the order `rollspec keys` lists them.
  std::vector<KeySpec> surface = texture_io::surface_keys();
  for (auto& t : surface) {
    // The solver's blocked force derives its strip from the contact radius unless the study sets these.
    if (t.key == "ny") t.doc += "; blocked_force = solver: strip width, the window's by default";
    if (t.key == "spacing")
      t.doc += "; blocked_force = solver: derived from the contact radius and the texture unless set";
  }
  return joined_keys(
      {ModalBeamSection::keys(),
       BallSection::keys(),
       ContactSection::keys(),
       RoughnessSection::keys(),
       SignalSection::keys(),
       SensorsSection::keys(),
       {SpectrumSection::skip_start_key(
           "time at the start of each record left out of the PSDs (start-up of the random response)", "0")},
       OutputSection::keys(),
       texture_io::psd_keys(),
       surface,
       StiffnessSection::keys(),
       BlockedForceSection::keys(),
       PathTableSection::keys(),
       EquivalentRoughnessSection::keys()});
}

beam::ModalBeam study_modal_beam(const KeyReader& s) { return ModalBeamSection::parse(s).modal_beam(); }

BallContact ball_on_beam_contact_pair(const KeyReader& s) {
  const ModalBeamSection beam = ModalBeamSection::parse(s);
  return ball_contact_pair(s, beam.properties.youngs_modulus, beam.poisson);
}

// The texture's 1 um default rms makes the template's 20 mm ball lose contact 81 % of the time;
// 30 nm (a fine ground track) keeps it in contact.
std::vector<FirstKey> ball_on_beam_first_keys() {
  return {first_key(&ModalBeamSection::properties, &beam::BeamProperties::length),
          first_key(&ModalBeamSection::properties, &beam::BeamProperties::width),
          first_key(&ModalBeamSection::properties, &beam::BeamProperties::thickness),
          first_key(&ModalBeamSection::properties, &beam::BeamProperties::youngs_modulus),
          first_key(&ModalBeamSection::properties, &beam::BeamProperties::density),
          first_key(&BallSection::radius),
          first_key(&BallSection::density),
          first_key(&BallSection::speed),
          first_key(&BallSection::start),
          first_key(&BallSection::end),
          first_key(&TextureSection::source),
          first_key(&TextureSection::rms, "3e-8"),
          first_key(&SensorsSection::positions)};
}

}  // namespace rollspec::scenes
