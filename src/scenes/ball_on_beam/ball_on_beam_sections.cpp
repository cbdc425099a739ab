#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"

#include "src/study/key_reader.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

BallOnBeamSections BallOnBeamSections::parse(const study::KeyReader& s) {
  BallOnBeamSections b(study::ModalBeamSection::parse(s));
  b.study = study::StudySection::parse(s);
  b.ensemble = study::EnsembleSection::parse(s);
  b.ball = study::BallSection::parse(s);
  b.signal = study::SignalSection::parse(s);
  b.sensors = study::SensorsSection::parse(s);
  b.spectrum = study::SpectrumSection::parse(s);
  b.output = study::OutputSection::parse(s);
  b.contact = study::ContactSection::parse(s);
  b.roughness = study::RoughnessSection::parse(s);
  b.texture = study::TextureSection::parse(s);
  b.equivalent_roughness = study::EquivalentRoughnessSection::parse(s);
  b.stiffness = study::StiffnessSection::parse(s);
  b.surface = study::SurfaceSection::parse(s);
  b.strip_surface = study::StripSurfaceSection::of(b.surface, b.texture);
  b.blocked_force = study::BlockedForceSection::parse(s);
  b.path_table = study::PathTableSection::parse(s);
  b.texture_psd = texture_io::study_psd(b.texture);
  const stiffness::TableSections tables{
      b.stiffness,           b.texture, b.surface, true, b.contact.uses_stiffness_table(), b.blocked_force,
      b.equivalent_roughness};
  b.tables = stiffness::TableStudy::of(tables, b.texture_psd, s);
  return b;
}

}  // namespace rollspec::scenes
