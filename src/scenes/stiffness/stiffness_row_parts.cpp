// What scene `stiffness`'s registry row (scene_registry.cpp) names besides its class and keys: its memory
// model and the references a run cites, and the relations of its dimensions.
#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/scene_references.hpp"
#include "src/scenes/stiffness/stiffness_scene.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/flat_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/surface_section.hpp"

namespace rollspec::scenes {

using study::BallSection;
using study::FlatSection;
using study::StiffnessSection;
using study::SurfaceSection;

std::vector<MemoryItem> stiffness_memory(const study::KeyReader& s, int /*threads*/) {
  const auto f = study::SurfaceSection::parse(s);
  return {contact_grid(static_cast<double>(f.nx), static_cast<double>(f.ny))};
}

std::vector<DimensionRelation> stiffness_relations(const study::KeyReader& s) {
  std::vector<DimensionRelation> out;
  const double r = s.real(BallSection::key(&BallSection::radius));
  const double a = hertz_radius(s, s.real(FlatSection::key(&FlatSection::youngs_modulus)),
                                s.real(FlatSection::key(&FlatSection::poisson)));
  ball_relations(a, r, out);
  approach_relations(s, a, out);
  const bool rough = study::read_choice(s, StiffnessSection::key(&StiffnessSection::surface),
                                        study::kStiffnessSurfaces) == study::StiffnessSurface::rough;
  add_surface_relations(s, rough, a, out);
  // The patch holds the contact, not the whole roughness: a roll-off up to a hundred patches long still
  // leaves it a share of the stated rms (the template's 1 mm over 128 um). A smooth ball on a smooth flat
  // draws no texture: its keys, written, are checked all the same.
  const double patch = s.real(SurfaceSection::key(&SurfaceSection::spacing)) *
                       static_cast<double>(s.integer(SurfaceSection::key(&SurfaceSection::nx)));
  add_texture_relations(s, SurfaceSection::key(&SurfaceSection::spacing),
                        rough || self_affine_written(s) ? 100.0 * patch : 0.0,
                        "a hundred times the surface patch nx x spacing", out);
  return out;
}

std::vector<std::string> stiffness_references(const study::KeyReader& s) {
  ReferenceIds ids = contact_solver_references();
  if (study::StiffnessSection::parse(s).rough)
    add_references(ids, isotropic_surface_references(study::SurfaceSection::parse(s).method));
  return ids;
}

}  // namespace rollspec::scenes
