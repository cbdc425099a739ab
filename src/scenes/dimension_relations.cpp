// The physical relations between the dimensional keys of the ball-on-beam, stiffness and texture
// scenes, and those of [texture] and [surface] the rolling pipe shares (dimension_plausibility.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "kernels/contact/hertz.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "src/io/number_text.hpp"
#include "src/scenes/dimension_plausibility.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::scenes {

// Keys named by the members they are read into (DeclaredSection::key): their names are written once, in
// the sections' declarations.
using study::BallSection;
using study::StiffnessSection;
using study::SurfaceSection;
using study::TextureSection;

std::string dim(double v, const char* unit) { return io::three_digits(v) + (*unit ? " " : "") + unit; }

bool self_affine_written(const study::KeyReader& s) {
  bool written = false;
  for (const std::string& k :
       {TextureSection::key(&TextureSection::hurst), TextureSection::key(&TextureSection::long_wavelength),
        TextureSection::key(&TextureSection::rolloff_wavelength),
        TextureSection::key(&TextureSection::short_wavelength), TextureSection::key(&TextureSection::rms_kind),
        TextureSection::key(&TextureSection::rms)})
    written = written || (s.has(k) && s.is_set(k));
  return written;
}

// [texture] of a self-affine source: its rms slope and height from the exact integrals (README Eq. 7-8),
// against 45 degrees, an atom and the span that holds the profile.
void add_texture_relations(const study::KeyReader& s, const std::string& span_key, double span,
                           const std::string& span_what, std::vector<DimensionRelation>& out) {
  // A self-affine source's keys, or any of them written for another source (a slip is a slip there too).
  // Measured profiles refuse the self-affine keys themselves, naming each (texture_io): nothing to relate.
  using study::TextureSource;
  if (!s.has(TextureSection::key(&TextureSection::source))) return;
  const TextureSource source =
      study::read_choice(s, TextureSection::key(&TextureSection::source), study::kTextureSources);
  if (source == TextureSource::profiles || (source != TextureSource::self_affine && !self_affine_written(s))) return;
  const double lr = s.real(TextureSection::key(&TextureSection::rolloff_wavelength)),
               ls = s.real(TextureSection::key(&TextureSection::short_wavelength));
  const double ll = s.real(TextureSection::key(&TextureSection::long_wavelength)),
               rms = s.real(TextureSection::key(&TextureSection::rms));
  const bool slope_kind = study::read_choice(s, TextureSection::key(&TextureSection::rms_kind), study::kRmsKinds) ==
                          texture::RmsTarget::slope;
  out.push_back({{TextureSection::key(&TextureSection::short_wavelength),
                  TextureSection::key(&TextureSection::rolloff_wavelength)},
                 ls < lr,
                 "the shortest roughness wavelength " + dim(ls, "m") + " is not below the roll-off wavelength " +
                     dim(lr, "m") + ": the self-affine range between them is empty"});
  if (ll > 0.0)
    out.push_back({{TextureSection::key(&TextureSection::long_wavelength),
                    TextureSection::key(&TextureSection::rolloff_wavelength)},
                   ll >= lr,
                   "the long-wavelength cut-off " + dim(ll, "m") + " lies below the roll-off wavelength " +
                       dim(lr, "m") + ": the plateau between them is empty"});
  out.push_back({{TextureSection::key(&TextureSection::short_wavelength)},
                 ls >= 1e-9,
                 "a roughness wavelength of " + dim(ls, "m") +
                     " spans fewer than a few atoms (0.1-0.3 nm each): continuum contact theory (D-6) stops "
                     "well above it"});
  if (span > 0.0)
    out.push_back({{TextureSection::key(&TextureSection::rolloff_wavelength), span_key},
                   lr <= span,
                   "the roll-off wavelength " + dim(lr, "m") + " exceeds " + span_what + " " + dim(span, "m") +
                       ": the rms height [texture] sets lies in wavelengths longer than " + span_what +
                       " holds, so what rolls over it is not that roughness"});
  if (!(ls < lr) || !(lr > 0.0) || !(ll < lr)) return;
  texture::SelfAffineSpec spec;
  spec.hurst = s.real(TextureSection::key(&TextureSection::hurst));
  spec.k_long = ll > 0.0 ? 2.0 * M_PI / ll : 0.0;
  spec.k_rolloff = 2.0 * M_PI / lr;
  spec.k_short = 2.0 * M_PI / ls;
  spec.target = slope_kind ? texture::RmsTarget::slope : texture::RmsTarget::height;
  spec.rms = rms;
  double slope = 0.0;
  try {
    slope = texture::SelfAffinePsd(spec).rms_slope();
  } catch (const std::exception&) {  // the texture's own checks refuse it, naming its key
    return;
  }
  const std::vector<std::string> keys =
      slope_kind ? std::vector<std::string>{TextureSection::key(&TextureSection::rms)}
                 : std::vector<std::string>{TextureSection::key(&TextureSection::rms),
                                            TextureSection::key(&TextureSection::short_wavelength),
                                            TextureSection::key(&TextureSection::rolloff_wavelength)};
  out.push_back({keys, slope <= 1.0,
                 "the self-affine profile's rms slope would be " + dim(slope, "") +
                     " "
                     "(steeper than 45 degrees): a surface this steep is no nominally flat plane, which the "
                     "contact laws and the half-space solver assume (D-6; ground and machined steel: 0.01-0.3)"});
}

// [surface]: the grid the contact solver (or the texture scene) draws heights on, and for the seed
// method its rms sigma and correlation lengths.
void add_surface_relations(const study::KeyReader& s, bool rough, double contact_radius,
                           std::vector<DimensionRelation>& out, bool contact_grid) {
  if (!s.has(SurfaceSection::key(&SurfaceSection::spacing))) return;
  const double dx = s.real(SurfaceSection::key(&SurfaceSection::spacing)),
               patch = dx * static_cast<double>(s.integer(SurfaceSection::key(&SurfaceSection::nx)));
  // The shipped AFM rows are sampled at 2.3 nm: a texture drawn on their grid is no contact's.
  if (contact_grid)
    out.push_back({{SurfaceSection::key(&SurfaceSection::spacing)},
                   dx >= 1e-8,
                   "a grid spacing of " + dim(dx, "m") +
                       " puts fewer than a hundred atoms in a cell: the continuum half-space (D-6) does not hold "
                       "there"});
  if (contact_radius > 0.0)
    out.push_back({{SurfaceSection::key(&SurfaceSection::spacing), BallSection::key(&BallSection::radius)},
                   dx <= contact_radius / 2.0,
                   "a grid spacing of " + dim(dx, "m") + " puts fewer than four cells across the Hertz contact 2a = " +
                       dim(2.0 * contact_radius, "m") + ": the solver cannot resolve the contact"});
  if (!rough && !s.is_set(SurfaceSection::key(&SurfaceSection::sigma)) &&
      !s.is_set(SurfaceSection::key(&SurfaceSection::correlation_x)) &&
      !s.is_set(SurfaceSection::key(&SurfaceSection::correlation_y)))
    return;
  const bool seed = study::read_choice(s, SurfaceSection::key(&SurfaceSection::method), study::kSurfaceMethods) ==
                    study::SurfaceMethod::seed;
  if (seed || s.is_set(SurfaceSection::key(&SurfaceSection::sigma)) ||
      s.is_set(SurfaceSection::key(&SurfaceSection::correlation_x)) ||
      s.is_set(SurfaceSection::key(&SurfaceSection::correlation_y))) {
    const double cx = s.real(SurfaceSection::key(&SurfaceSection::correlation_x)),
                 cy = s.real(SurfaceSection::key(&SurfaceSection::correlation_y));
    const double sigma = s.real(SurfaceSection::key(&SurfaceSection::sigma)), c = std::min(cx, cy);
    out.push_back({{SurfaceSection::key(&SurfaceSection::sigma), SurfaceSection::key(&SurfaceSection::correlation_x),
                    SurfaceSection::key(&SurfaceSection::correlation_y)},
                   sigma <= c,
                   "the surface's rms height " + dim(sigma, "m") + " exceeds its correlation length " + dim(c, "m") +
                       ": slopes beyond 45 degrees, no nominally flat plane (the half-space solver assumes small "
                       "slopes, D-6)"});
    out.push_back({{SurfaceSection::key(&SurfaceSection::correlation_x),
                    SurfaceSection::key(&SurfaceSection::correlation_y), SurfaceSection::key(&SurfaceSection::spacing)},
                   std::max(cx, cy) <= 10.0 * patch,
                   "a correlation length of " + dim(std::max(cx, cy), "m") +
                       " exceeds ten times the surface patch nx x "
                       "spacing = " +
                       dim(patch, "m") + ": the patch holds a sliver of one correlated height, no rough surface"});
    if (!seed) return;  // written for another method: the grid's spacing is not theirs to resolve
    out.push_back({{SurfaceSection::key(&SurfaceSection::correlation_x),
                    SurfaceSection::key(&SurfaceSection::correlation_y), SurfaceSection::key(&SurfaceSection::spacing)},
                   c >= dx,
                   "a correlation length of " + dim(c, "m") + " is shorter than the grid spacing " + dim(dx, "m") +
                       ": the grid holds no correlated heights"});
  } else if (s.has(TextureSection::key(&TextureSection::source)) &&
             study::read_choice(s, TextureSection::key(&TextureSection::source), study::kTextureSources) ==
                 study::TextureSource::self_affine) {
    const double ls = s.real(TextureSection::key(&TextureSection::short_wavelength));
    out.push_back(
        {{SurfaceSection::key(&SurfaceSection::spacing), TextureSection::key(&TextureSection::short_wavelength)},
         dx <= ls / 2.0,
         "a grid spacing of " + dim(dx, "m") + " cannot represent the shortest roughness wavelength " + dim(ls, "m") +
             " (Nyquist: spacing <= wavelength / 2)"});
  }
}

double e_star(double e1, double nu1, double e2, double nu2) {
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

// The ball's Hertz contact radius under its own weight (1 N without gravity) on a flat of (e, nu).
double hertz_radius(const study::KeyReader& s, double e, double nu) {
  const double r = s.real(BallSection::key(&BallSection::radius)), g = s.real(BallSection::key(&BallSection::gravity));
  const double weight =
      g > 0.0 ? 4.0 / 3.0 * M_PI * r * r * r * s.real(BallSection::key(&BallSection::density)) * g : 1.0;
  return contact::hertz::contact_radius_at_load(r,
                                                e_star(s.real(BallSection::key(&BallSection::youngs_modulus)),
                                                       s.real(BallSection::key(&BallSection::poisson)), e, nu),
                                                weight);
}

// The ball alone: its Hertz contact against atoms and against Hertz theory's small contacts.
void ball_relations(double a, double r, std::vector<DimensionRelation>& out) {
  out.push_back({{BallSection::key(&BallSection::radius)},
                 a >= 1e-9,
                 "the Hertz contact radius under the ball's weight would be " + dim(a, "m") +
                     ", a few atoms: continuum contact (Hertz, D-6) does not hold at that size"});
  out.push_back({{BallSection::key(&BallSection::radius)},
                 a <= 0.1 * r,
                 "the Hertz contact radius under the ball's weight would be " + dim(a, "m") + ", " + dim(a / r, "") +
                     " "
                     "of the radius: Hertz theory needs a/R <= 0.1"});
}

// [stiffness] approach_max against the ball: the table must pass the static compression and stay a
// small contact (sqrt(R w) <= R / 10).
void approach_relations(const study::KeyReader& s, double a, std::vector<DimensionRelation>& out) {
  const double w = s.real(StiffnessSection::key(&StiffnessSection::approach_max)),
               r = s.real(BallSection::key(&BallSection::radius)), d0 = a * a / r;
  out.push_back({{StiffnessSection::key(&StiffnessSection::approach_max), BallSection::key(&BallSection::radius)},
                 w >= d0,
                 "the table stops at an approach of " + dim(w, "m") + ", below the ball's static compression " +
                     dim(d0, "m") + " under its weight: the run would read the law beyond the table"});
  out.push_back({{StiffnessSection::key(&StiffnessSection::approach_max), BallSection::key(&BallSection::radius)},
                 w <= 0.01 * r,
                 "an approach of " + dim(w, "m") + " is " + dim(w / r, "") +
                     " "
                     "of the ball's radius: its contact radius sqrt(R w) passes R / 10, beyond the half-space "
                     "theory of a small contact (D-6)"});
  const double rms = s.real(StiffnessSection::key(&StiffnessSection::ball_rms));
  if (rms > 0.0)
    out.push_back({{StiffnessSection::key(&StiffnessSection::ball_rms), BallSection::key(&BallSection::radius)},
                   rms <= 0.01 * r && rms >= 1e-10,
                   "a ball roughness of " + dim(rms, "m") + " rms on a ball of radius " + dim(r, "m") +
                       ": a sphere's roughness lies between an atom (1e-10 m) and a hundredth of its radius"});
}

}  // namespace rollspec::scenes
