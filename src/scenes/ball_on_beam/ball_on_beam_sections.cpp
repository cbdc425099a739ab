#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"

#include "src/study/key_reader.hpp"
#include "src/study/sections/parse_sections.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

BallOnBeamSections BallOnBeamSections::parse(const study::KeyReader& s) {
  BallOnBeamSections b(study::ModalBeamSection::parse(s));
  study::parse_sections(s, b.study, b.ensemble, b.ball, b.signal, b.sensors, b.spectrum, b.output, b.contact,
                        b.roughness, b.texture, b.equivalent_roughness, b.stiffness, b.surface);
  b.strip_surface = study::StripSurfaceSection::of(b.surface, b.texture);
  study::parse_sections(s, b.blocked_force, b.path_table);
  b.texture_psd = texture_io::study_psd(b.texture);
  const stiffness::TableSections tables{
      b.stiffness,           b.texture, b.surface, true, b.contact.uses_stiffness_table(), b.blocked_force,
      b.equivalent_roughness};
  b.tables = stiffness::TableStudy::of(tables, b.texture_psd, s);
  return b;
}

}  // namespace rollspec::scenes
