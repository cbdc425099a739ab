#pragma once
// Scene `ball-on-beam`'s study, parsed once into its typed sections, with what the sections
// describe already resolved: the modal beam of [beam], the roughness PSD of [texture] (its table or
// profile files read) and what the contact table stages take (stiffness::TableStudy). The scene, its settings and the
// memory estimate start from this value; none of them sees the study's keys.
#include "kernels/beam/modal_beam.hpp"
#include "kernels/texture/psd.hpp"
#include "src/stiffness/table_study.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/ensemble_section.hpp"
#include "src/study/sections/equivalent_roughness_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/output_section.hpp"
#include "src/study/sections/path_table_section.hpp"
#include "src/study/sections/roughness_section.hpp"
#include "src/study/sections/sensors_section.hpp"
#include "src/study/sections/signal_section.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/strip_surface_section.hpp"
#include "src/study/sections/study_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

struct BallOnBeamSections {
  study::ModalBeamSection beam;
  beam::ModalBeam modal_beam;  // of [beam]: its modes, computed once
  study::StudySection study;
  study::EnsembleSection ensemble;
  study::BallSection ball;
  study::SignalSection signal;
  study::SensorsSection sensors;
  study::SpectrumSection spectrum;
  study::OutputSection output;
  study::ContactSection contact;
  study::RoughnessSection roughness;
  study::TextureSection texture;
  study::EquivalentRoughnessSection equivalent_roughness;
  study::StiffnessSection stiffness;
  study::SurfaceSection surface;
  study::StripSurfaceSection strip_surface;  // of [surface] and [texture]
  study::BlockedForceSection blocked_force;
  study::PathTableSection path_table;
  texture::Psd texture_psd;      // the roughness PSD [texture] describes (texture_io::study_psd)
  stiffness::TableStudy tables;  // what the contact table stages take

  static BallOnBeamSections parse(const study::KeyReader& s);

 private:
  explicit BallOnBeamSections(const study::ModalBeamSection& b) : beam(b), modal_beam(b.modal_beam()) {}
};

}  // namespace rollspec::scenes
