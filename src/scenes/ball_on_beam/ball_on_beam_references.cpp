// The papers and theory-note equations a run of a `ball-on-beam` study cites (its registry row's `references`),
// from the contact law and filter the study chose.
#include "src/scenes/ball_on_beam/ball_on_beam.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"
#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::scenes {

std::vector<std::string> ball_on_beam_references(const study::KeyReader& s) {
  const BallOnBeamSections sections = BallOnBeamSections::parse(s);
  const BallOnBeamSettings b = read_ball_on_beam_settings(sections);
  ReferenceIds ids = {"seed 001", "D-1", "D-3", "D-8", "D-9"};
  switch (b.contact) {
    case ContactModel::hertz:
      add_references(ids, {"D-10", "Johnson 1985"});
      break;
    case ContactModel::table:
    case ContactModel::literal:
      add_references(ids, {"D-10"});
      add_references(ids, contact_solver_references());
      if (sections.stiffness.rough) add_references(ids, isotropic_surface_references(sections.surface.method));
      break;
    case ContactModel::linearised_spring:
      add_references(ids, {"seed 002", "D-11"});
      break;
    case ContactModel::linearised_solver:
      add_references(ids, {"seed 002", "D-11", "BF-1..BF-7"});
      add_references(ids, contact_solver_references());
      break;
    case ContactModel::path:
      add_references(ids, {"D-10", "B41..B46"});
      add_references(ids, contact_solver_references());
      break;
  }
  const bool filtered = b.filter_applied == b.filter_name;  // a patch filter is not applied on a strip law
  if (filtered && b.filter == ContactFilter::patch) add_references(ids, {"B35", "Johnson 1985"});
  if (b.filter == ContactFilter::iso2d) add_references(ids, {"texture Eq. 36-40", "Johnson 1985"});
  if (b.filter == ContactFilter::solver) {
    add_references(ids, {"ER-1..ER-7"});
    add_references(ids, contact_solver_references());
  }
  add_references(ids, ensemble_spectra_references(s));
  return ids;
}

}  // namespace rollspec::scenes
