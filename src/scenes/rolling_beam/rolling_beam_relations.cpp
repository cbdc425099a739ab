// Scene `rolling-beam`'s physical relations between its dimensional keys (dimension_plausibility.hpp): a
// disc or puck of a solid's density, walls the body can meet and does not start inside.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/rolling_beam/rolling_beam.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/rolling_analysis_section.hpp"
#include "src/study/sections/rolling_body_sections.hpp"

namespace rollspec::scenes {

using study::DiscSection;
using study::FlyingBeamSection;
using study::PuckSection;
using study::RollingAnalysisSection;
using study::StraightBeamSection;

namespace {

// "x, y, z; x, y, z" as points.
std::vector<Eigen::Vector3d> vectors(const std::string& text) {
  std::vector<Eigen::Vector3d> out;
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ';');) {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    std::istringstream c(item);
    std::string part;
    for (int i = 0; i < 3 && std::getline(c, part, ','); ++i) v[i] = std::strtod(part.c_str(), nullptr);
    out.push_back(v);
  }
  return out;
}

// The body kinds' own sections: a key written for another kind changes nothing, which is a slip too.
void refuse_unused_sections(const study::KeyReader& s, study::BodyKind kind) {
  using study::BodyKind;
  const std::vector<std::pair<std::string, std::vector<BodyKind>>> owner = {{"puck", {BodyKind::puck}},
                                                                            {"flying_beam", {BodyKind::flying_beam}},
                                                                            {"disc", {BodyKind::disc, BodyKind::puck}},
                                                                            {"beam", {BodyKind::beam}}};
  for (const auto& [section, kinds] : owner) {
    if (std::find(kinds.begin(), kinds.end(), kind) != kinds.end()) continue;
    for (const auto& k : s.keys())
      if (k.section == section && s.is_set(k.full_name()))
        s.refuse(k.full_name(), "has no effect: [body] kind = " + study::spelling_of(study::kBodyKinds, kind) +
                                    " uses no [" + section +
                                    "] (remove it, or set [body] kind to the body it describes)");
  }
}

}  // namespace

std::vector<DimensionRelation> rolling_beam_relations(const study::KeyReader& s) {
  std::vector<DimensionRelation> out;
  using study::BodyKind;
  const BodyKind kind = study::BodySection::parse(s).kind;
  refuse_unused_sections(s, kind);
  const double t_end = s.real(RollingAnalysisSection::key(&RollingAnalysisSection::t_end));
  if (kind == BodyKind::disc || kind == BodyKind::puck) {
    const double r = s.real(DiscSection::key(&DiscSection::radius)),
                 len = s.real(DiscSection::key(&DiscSection::length)), m = s.real(DiscSection::key(&DiscSection::mass));
    const double rho = m / (M_PI * r * r * len);
    out.push_back({{DiscSection::key(&DiscSection::radius), DiscSection::key(&DiscSection::length)},
                   rho >= 10.0 && rho <= 25000.0,
                   "a disc of " + dim(m, "kg") + " with radius " + dim(r, "m") + " and length " + dim(len, "m") +
                       " would have a density of " + dim(rho, "kg/m^3") +
                       ", outside every solid's (10 kg/m^3 for foams to 22600 for osmium)"});
  }
  if (kind == BodyKind::puck) {  // a triangular pulse's impulse F T / 2 moves the puck at most that far in t_end
    const double r = s.real(DiscSection::key(&DiscSection::radius)),
                 hw = s.real(PuckSection::key(&PuckSection::half_width));
    const double reach = r + s.real(PuckSection::key(&PuckSection::force_peak)) *
                                 s.real(PuckSection::key(&PuckSection::pulse)) / 2.0 /
                                 s.real(DiscSection::key(&DiscSection::mass)) * t_end;
    out.push_back({{PuckSection::key(&PuckSection::half_width), DiscSection::key(&DiscSection::radius)},
                   hw > r,
                   "walls at +-" + dim(hw, "m") + " cut through a puck of radius " + dim(r, "m") + " at the centre"});
    out.push_back({{PuckSection::key(&PuckSection::half_width)},
                   hw <= 10.0 * reach,
                   "walls at +-" + dim(hw, "m") + " lie beyond ten times the farthest the puck can travel in t_end (" +
                       dim(reach, "m") + ", its pulse's impulse over its mass): it never meets them"});
  }
  if (kind == BodyKind::flying_beam) {  // seed 4.4: a 1000 m beam along x on y = 0, spheres of radius 25 m
    const double wall = s.real(FlyingBeamSection::key(&FlyingBeamSection::wall_distance)),
                 clear = (wall - 500.0) / std::sqrt(2.0);
    const double reach = s.real(FlyingBeamSection::key(&FlyingBeamSection::force_peak)) *
                         s.real(FlyingBeamSection::key(&FlyingBeamSection::ramp)) / 2.0 / 1.3 * t_end;
    out.push_back({{FlyingBeamSection::key(&FlyingBeamSection::wall_distance)},
                   clear >= 25.0,
                   "an oblique wall at " + dim(wall, "m") +
                       " cuts through the beam where it starts (its end at x = "
                       "500 m, contact spheres of radius 25 m)"});
    out.push_back({{FlyingBeamSection::key(&FlyingBeamSection::wall_distance)},
                   clear <= 10.0 * reach,
                   "an oblique wall at " + dim(wall, "m") +
                       " lies beyond ten times the farthest the beam can fly in "
                       "t_end (" +
                       dim(reach, "m") + ", its force's impulse over its 1.3 kg): it never meets it"});
  }
  if (kind == BodyKind::beam) {  // a geometrically exact beam: slender, and not starting deep inside a plane
    const double d = s.real(StraightBeamSection::key(&StraightBeamSection::diameter));
    const auto ends = vectors(s.text(StraightBeamSection::key(&StraightBeamSection::start)) + ";" +
                              s.text(StraightBeamSection::key(&StraightBeamSection::end)));
    const double length = ends.size() == 2 ? (ends[1] - ends[0]).norm() : 0.0;
    out.push_back({{StraightBeamSection::key(&StraightBeamSection::diameter)},
                   d <= length / 2.0,
                   "a beam " + dim(d, "m") + " across and " + dim(length, "m") + " long is no slender beam"});
  }
  const double pen = s.real(RollingAnalysisSection::key(&RollingAnalysisSection::max_new_penetration));
  if (pen > 0.0)
    out.push_back({{RollingAnalysisSection::key(&RollingAnalysisSection::max_new_penetration)},
                   pen <= 1.0 && pen >= 1e-12,
                   "a largest new penetration of " + dim(pen, "m") +
                       ": a penalty contact's penetration is a small fraction of the body's size"});
  return out;
}

}  // namespace rollspec::scenes
