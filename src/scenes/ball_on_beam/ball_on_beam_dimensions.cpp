// The physical relations between a ball-on-beam study's lengths, thicknesses, radii, rms heights and
// speed (dimension_plausibility.hpp): the beam against itself and its own weight, the ball against
// the beam, the traverse against the span, the roughness against the span, the tables against the
// ball. Each is a statement a slender steel beam and a rolling ball satisfy by a wide margin.
#include <algorithm>
#include <cmath>

#include "src/scenes/dimension_plausibility.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/path_table_section.hpp"
#include "src/study/sections/roughness_section.hpp"
#include "src/study/sections/stiffness_section.hpp"

namespace rollspec::scenes {

using study::BallSection;
using study::BlockedForceSection;
using study::ContactSection;
using study::ModalBeamSection;
using study::PathTableSection;
using study::RoughnessSection;
using study::StiffnessSection;

namespace {

// Keys are named by the members they are read into (DeclaredSection::key): their names are written once, in
// the sections' declarations.
template <class T>
std::string beam_key(T beam::BeamProperties::*field) {
  return ModalBeamSection::key(&ModalBeamSection::properties, field);
}

// The beam: slender (t << L), a beam not a plate (b <= L), not a blade standing on edge, and not
// sagging under its own weight by more than its thickness (clamped: q L^4 / 384 EI; simply
// supported: 5 q L^4 / 384 EI, q = rho g b t, I = b t^3 / 12).
void beam_relations(const study::KeyReader& s, std::vector<DimensionRelation>& out) {
  const double L = s.real(beam_key(&beam::BeamProperties::length)),
               t = s.real(beam_key(&beam::BeamProperties::thickness)),
               b = s.real(beam_key(&beam::BeamProperties::width));
  const double leff = s.real(beam_key(&beam::BeamProperties::effective_length)), span = std::max(L, leff);
  const bool clamped = study::read_choice(s, beam_key(&beam::BeamProperties::support), study::kBeamSupports) ==
                       beam::Support::clamped_clamped;
  const double g = 9.81;  // the beam's own weight on Earth ([ball] gravity loads the ball, a model choice)
  const double sag = (clamped ? 1.0 : 5.0) * s.real(beam_key(&beam::BeamProperties::density)) * g * std::pow(span, 4) /
                     (32.0 * s.real(beam_key(&beam::BeamProperties::youngs_modulus)) * t * t);
  const std::vector<std::string> span_keys =
      leff > L ? std::vector<std::string>{ModalBeamSection::key(&ModalBeamSection::properties,
                                                                &beam::BeamProperties::effective_length),
                                          ModalBeamSection::key(&ModalBeamSection::properties,
                                                                &beam::BeamProperties::thickness),
                                          ModalBeamSection::key(&ModalBeamSection::properties,
                                                                &beam::BeamProperties::length)}
               : std::vector<std::string>{beam_key(&beam::BeamProperties::length),
                                          beam_key(&beam::BeamProperties::thickness)};
  out.push_back({{beam_key(&beam::BeamProperties::thickness), beam_key(&beam::BeamProperties::length)},
                 t <= L / 5.0,
                 "a beam " + dim(t / L, "") +
                     " times its span thick is no slender beam: Euler-Bernoulli theory "
                     "(D-8, D-9) needs the thickness well below the span (here " +
                     dim(L, "m") + ")"});
  out.push_back({span_keys, sag <= t,
                 "the beam would sag " + dim(sag, "m") + " under its own weight, more than its thickness " +
                     dim(t, "m") + ": linear beam theory needs deflections small against the thickness"});
  out.push_back({{beam_key(&beam::BeamProperties::width), beam_key(&beam::BeamProperties::length)},
                 b <= L,
                 "a beam " + dim(b, "m") + " wide over a span of " + dim(L, "m") +
                     " is a plate, not a beam: the modal beam (D-8) bends along its span only"});
  out.push_back({{beam_key(&beam::BeamProperties::width), beam_key(&beam::BeamProperties::thickness)},
                 t <= 20.0 * b,
                 "a beam " + dim(t, "m") + " deep and only " + dim(b, "m") +
                     " wide is a blade on edge: it buckles sideways under the ball, which the beam model (bending "
                     "in one plane) does not hold"});
  if (leff > 0.0)
    out.push_back({{beam_key(&beam::BeamProperties::effective_length), beam_key(&beam::BeamProperties::length)},
                   leff <= 2.0 * L,
                   "an effective length of " + dim(leff, "m") + " over a span of " + dim(L, "m") +
                       ": the unconstrained part it adds is a small part of the span (seed 002: 30 mm of 390)"});
}

// The ball on the beam: it fits on the span, its contact on the beam's width, its weight on the beam
// (midspan deflection W L^3 / 192 EI clamped, / 48 EI simply supported), its traverse on the span.
void ball_against_beam(const study::KeyReader& s, double a, std::vector<DimensionRelation>& out) {
  const double L = s.real(beam_key(&beam::BeamProperties::length)),
               t = s.real(beam_key(&beam::BeamProperties::thickness)),
               b = s.real(beam_key(&beam::BeamProperties::width));
  const double r = s.real(BallSection::key(&BallSection::radius)), x0 = s.real(BallSection::key(&BallSection::start)),
               x1 = s.real(BallSection::key(&BallSection::end));
  const double g = s.real(BallSection::key(&BallSection::gravity));
  const double weight =
      g > 0.0 ? 4.0 / 3.0 * M_PI * r * r * r * s.real(BallSection::key(&BallSection::density)) * g : 1.0;
  const bool clamped = study::read_choice(s, beam_key(&beam::BeamProperties::support), study::kBeamSupports) ==
                       beam::Support::clamped_clamped;
  const double span = std::max(L, s.real(beam_key(&beam::BeamProperties::effective_length)));
  const double deflection =
      weight * span * span * span /
      ((clamped ? 192.0 : 48.0) * s.real(beam_key(&beam::BeamProperties::youngs_modulus)) * b * t * t * t / 12.0);
  out.push_back({{BallSection::key(&BallSection::radius), beam_key(&beam::BeamProperties::length)},
                 2.0 * r <= L,
                 "a ball " + dim(2.0 * r, "m") + " across does not fit on a span of " + dim(L, "m")});
  out.push_back({{beam_key(&beam::BeamProperties::width), BallSection::key(&BallSection::radius)},
                 2.0 * a <= b,
                 "the ball's Hertz contact 2a = " + dim(2.0 * a, "m") + " under its weight is wider than the beam (" +
                     dim(b, "m") + "): a point contact on a beam needs a contact narrower than the beam"});
  out.push_back({{BallSection::key(&BallSection::radius), beam_key(&beam::BeamProperties::thickness),
                  beam_key(&beam::BeamProperties::length)},
                 deflection <= t,
                 "the beam's static deflection under the ball's weight W = " + dim(weight, "N") + " reaches " +
                     dim(deflection, "m") + " at midspan, more than the beam thickness " + dim(t, "m") +
                     ": linear beam theory needs deflections small against the thickness"});
  out.push_back({{BallSection::key(&BallSection::start), beam_key(&beam::BeamProperties::length)},
                 x0 < L,
                 "the ball starts at " + dim(x0, "m") + ", beyond the span [0, " + dim(L, "m") + "]"});
  out.push_back({{BallSection::key(&BallSection::end), beam_key(&beam::BeamProperties::length)},
                 x1 <= L,
                 "the ball ends at " + dim(x1, "m") + ", beyond the span [0, " + dim(L, "m") + "]"});
  out.push_back({{BallSection::key(&BallSection::end), BallSection::key(&BallSection::start)},
                 x1 > x0,
                 "the ball ends at " + dim(x1, "m") + ", not after its start " + dim(x0, "m")});
  const double v = s.real(BallSection::key(&BallSection::speed));
  out.push_back({{BallSection::key(&BallSection::speed)},
                 v <= 100.0,
                 "a rolling ball at " + dim(v, "m/s") + " (" + dim(3.6 * v, "km/h") +
                     ") is beyond any rig: a ball on a beam rolls at walking or running speed"});
}

// The line roughness's own sampling, and the contact strips of the solver stages, against the span.
void strip_relations(const study::KeyReader& s, std::vector<DimensionRelation>& out) {
  const double L = s.real(beam_key(&beam::BeamProperties::length)),
               dx = s.real(RoughnessSection::key(&RoughnessSection::spacing));
  if (dx > 0.0)
    out.push_back({{RoughnessSection::key(&RoughnessSection::spacing), beam_key(&beam::BeamProperties::length)},
                   dx >= 1e-9 && dx <= L / 4.0,
                   "a roughness sample spacing of " + dim(dx, "m") + " over a span of " + dim(L, "m") +
                       ": between a few atoms (1e-9 m) and a quarter of the span"});
  for (const std::string& key : {BlockedForceSection::key(&BlockedForceSection::strip_length),
                                 PathTableSection::key(&PathTableSection::strip_length)}) {
    const double strip = s.real(key);
    if (strip > 0.0)
      out.push_back({{key, beam_key(&beam::BeamProperties::length)},
                     strip <= L,
                     "a contact strip of " + dim(strip, "m") + " is longer than the span " + dim(L, "m") +
                         " the ball rolls along"});
  }
}

}  // namespace

std::vector<DimensionRelation> ball_on_beam_relations(const study::KeyReader& s) {
  std::vector<DimensionRelation> out;
  const double r = s.real(BallSection::key(&BallSection::radius));
  const double a = hertz_radius(s, s.real(beam_key(&beam::BeamProperties::youngs_modulus)),
                                s.real(ModalBeamSection::key(&ModalBeamSection::poisson)));
  beam_relations(s, out);
  ball_relations(a, r, out);
  ball_against_beam(s, a, out);
  strip_relations(s, out);
  add_texture_relations(s, beam_key(&beam::BeamProperties::length), s.real(beam_key(&beam::BeamProperties::length)),
                        "the span", out);
  // The grid and the tables carry the contact only where a table or a solver stage is built.
  using namespace study;
  const ContactLaw law = read_choice(s, ContactSection::key(&ContactSection::law), kContactLaws);
  const bool table = law == ContactLaw::table || law == ContactLaw::literal;
  const bool solver =
      law == ContactLaw::path ||
      read_choice(s, ContactSection::key(&ContactSection::filter), kContactFilters) == ContactFilter::solver ||
      read_choice(s, ContactSection::key(&ContactSection::blocked_force), kBlockedForceSources) ==
          BlockedForceSource::solver;
  // Written, the keys of a stage the study does not build are checked too: a slip there is a slip.
  bool surface_written = false;
  for (const auto& k : s.keys())
    surface_written = surface_written || (k.section == "surface" && s.is_set(k.full_name()));
  if (table || s.is_set(StiffnessSection::key(&StiffnessSection::approach_max)) ||
      s.is_set(StiffnessSection::key(&StiffnessSection::ball_rms)))
    approach_relations(s, a, out);
  if (table || solver || surface_written)
    add_surface_relations(s,
                          solver || read_choice(s, StiffnessSection::key(&StiffnessSection::surface),
                                                kStiffnessSurfaces) == StiffnessSurface::rough,
                          a, out);
  return out;
}

}  // namespace rollspec::scenes
