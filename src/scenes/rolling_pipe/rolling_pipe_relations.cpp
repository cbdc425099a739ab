// Scene `rolling-pipe`'s physical relations between its dimensional keys (dimension_plausibility.hpp): a
// slender tube on a floor that holds it and its roll.
#include <algorithm>
#include <cmath>

#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/rolling_pipe/rolling_pipe.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::scenes {

std::vector<DimensionRelation> rolling_pipe_relations(const study::KeyReader& s) {
  std::vector<DimensionRelation> out;
  const double L = s.real("pipe.length"), D = s.real("pipe.diameter"), di = s.real("pipe.inner_diameter");
  const double v = s.real("roll.speed"), distance = s.real("roll.distance");
  out.push_back({{"pipe.diameter", "pipe.length"},
                 D <= L / 2.0,
                 "a tube " + dim(D, "m") + " across and " + dim(L, "m") +
                     " long is no slender tube: its beam elements need a length well above the diameter"});
  out.push_back({{"pipe.inner_diameter", "pipe.diameter"},
                 di < D,
                 "an inner diameter of " + dim(di, "m") + " leaves no wall inside the outer " + dim(D, "m")});
  out.push_back({{"roll.speed"},
                 v <= 100.0,
                 "a tube rolling at " + dim(v, "m/s") + " (" + dim(3.6 * v, "km/h") +
                     ") is beyond any rig: a tube on a floor rolls at walking or running speed"});
  out.push_back({{"roughness.spacing", "pipe.diameter"},
                 s.real("roughness.spacing") <= D,
                 "a floor sampled every " + dim(s.real("roughness.spacing"), "m") + " is flat under a tube " +
                     dim(D, "m") + " across: the contact spheres meet one sample"});
  const bool line = study::PipeRoughnessSection::parse(s).line;
  double floor_length = distance + D;
  if (!line) {  // the grid holds the rolled strip (x) and the tube across it (y)
    const double dx = s.real("surface.spacing");
    const double fx = dx * static_cast<double>(s.integer("surface.nx") - 1),
                 fy = dx * static_cast<double>(s.integer("surface.ny") - 1);
    floor_length = fx;
    out.push_back({{"pipe.length", "surface.spacing"},
                   L <= fy,
                   "a tube " + dim(L, "m") + " long lies across a floor only " + dim(fy, "m") +
                       " wide (ny x spacing): its ends hang off the surface"});
    out.push_back(
        {{"roll.distance", "surface.spacing"},
         distance <= fx,
         "a roll of " + dim(distance, "m") + " runs off a floor only " + dim(fx, "m") + " long (nx x spacing)"});
    out.push_back({{"surface.spacing", "pipe.diameter"},
                   dx <= D,
                   "a floor grid spacing of " + dim(dx, "m") + " is flat under a tube " + dim(D, "m") + " across"});
    add_surface_relations(s, true, 0.0, out);
  }
  add_texture_relations(s, "roll.distance", floor_length, "the rolled floor", out);
  const study::TextureSection texture = study::TextureSection::parse(s);
  if (texture.source == study::TextureSource::self_affine && texture.rms_kind == texture::RmsTarget::height)
    out.push_back({{"texture.rms", "pipe.diameter"},
                   s.real("texture.rms") <= D / 10.0,
                   "a floor roughness of " + dim(s.real("texture.rms"), "m") + " rms is as tall as the tube (" +
                       dim(D, "m") + " across): a tube rolls over roughness well below its size"});
  return out;
}

}  // namespace rollspec::scenes
