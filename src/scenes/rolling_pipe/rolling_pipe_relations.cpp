// Scene `rolling-pipe`'s physical relations between its dimensional keys (dimension_plausibility.hpp): a
// slender tube on a floor that holds it and its roll.
#include <algorithm>
#include <cmath>

#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/rolling_pipe/rolling_pipe.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::scenes {

using study::PipeRoughnessSection;
using study::PipeSection;
using study::RollSection;
using study::SurfaceSection;
using study::TextureSection;

std::vector<DimensionRelation> rolling_pipe_relations(const study::KeyReader& s) {
  std::vector<DimensionRelation> out;
  const double L = s.real(PipeSection::key(&PipeSection::length)), D = s.real(PipeSection::key(&PipeSection::diameter)),
               di = s.real(PipeSection::key(&PipeSection::inner_diameter));
  const double v = s.real(RollSection::key(&RollSection::speed)),
               distance = s.real(RollSection::key(&RollSection::distance));
  out.push_back({{PipeSection::key(&PipeSection::diameter), PipeSection::key(&PipeSection::length)},
                 D <= L / 2.0,
                 "a tube " + dim(D, "m") + " across and " + dim(L, "m") +
                     " long is no slender tube: its beam elements need a length well above the diameter"});
  out.push_back({{PipeSection::key(&PipeSection::inner_diameter), PipeSection::key(&PipeSection::diameter)},
                 di < D,
                 "an inner diameter of " + dim(di, "m") + " leaves no wall inside the outer " + dim(D, "m")});
  out.push_back({{RollSection::key(&RollSection::speed)},
                 v <= 100.0,
                 "a tube rolling at " + dim(v, "m/s") + " (" + dim(3.6 * v, "km/h") +
                     ") is beyond any rig: a tube on a floor rolls at walking or running speed"});
  out.push_back({{PipeRoughnessSection::key(&PipeRoughnessSection::spacing), PipeSection::key(&PipeSection::diameter)},
                 s.real(PipeRoughnessSection::key(&PipeRoughnessSection::spacing)) <= D,
                 "a floor sampled every " +
                     dim(s.real(PipeRoughnessSection::key(&PipeRoughnessSection::spacing)), "m") +
                     " is flat under a tube " + dim(D, "m") + " across: the contact spheres meet one sample"});
  const bool line = study::PipeRoughnessSection::parse(s).line;
  double floor_length = distance + D;
  if (!line) {  // the grid holds the rolled strip (x) and the tube across it (y)
    const double dx = s.real(SurfaceSection::key(&SurfaceSection::spacing));
    const double fx = dx * static_cast<double>(s.integer(SurfaceSection::key(&SurfaceSection::nx)) - 1),
                 fy = dx * static_cast<double>(s.integer(SurfaceSection::key(&SurfaceSection::ny)) - 1);
    floor_length = fx;
    out.push_back({{PipeSection::key(&PipeSection::length), SurfaceSection::key(&SurfaceSection::spacing)},
                   L <= fy,
                   "a tube " + dim(L, "m") + " long lies across a floor only " + dim(fy, "m") +
                       " wide (ny x spacing): its ends hang off the surface"});
    out.push_back(
        {{RollSection::key(&RollSection::distance), SurfaceSection::key(&SurfaceSection::spacing)},
         distance <= fx,
         "a roll of " + dim(distance, "m") + " runs off a floor only " + dim(fx, "m") + " long (nx x spacing)"});
    out.push_back({{SurfaceSection::key(&SurfaceSection::spacing), PipeSection::key(&PipeSection::diameter)},
                   dx <= D,
                   "a floor grid spacing of " + dim(dx, "m") + " is flat under a tube " + dim(D, "m") + " across"});
    add_surface_relations(s, true, 0.0, out);
  }
  add_texture_relations(s, RollSection::key(&RollSection::distance), floor_length, "the rolled floor", out);
  const study::TextureSection texture = study::TextureSection::parse(s);
  if (texture.source == study::TextureSource::self_affine && texture.rms_kind == texture::RmsTarget::height)
    out.push_back({{TextureSection::key(&TextureSection::rms), PipeSection::key(&PipeSection::diameter)},
                   s.real(TextureSection::key(&TextureSection::rms)) <= D / 10.0,
                   "a floor roughness of " + dim(s.real(TextureSection::key(&TextureSection::rms)), "m") +
                       " rms is as tall as the tube (" + dim(D, "m") +
                       " across): a tube rolls over roughness well below its size"});
  return out;
}

}  // namespace rollspec::scenes
