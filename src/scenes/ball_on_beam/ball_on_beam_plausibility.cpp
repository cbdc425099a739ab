#include "src/scenes/ball_on_beam/ball_on_beam_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "src/io/number_text.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"

namespace rollspec::scenes {

namespace {

// Hertz theory holds for a contact radius small against the ball (a/R <= 0.1) and the point
// contact on a beam for a contact narrower than the beam.
void check_contact(const BallOnBeamSettings& b, std::vector<std::string>& warnings) {
  const double a = b.contact_half_width, r = b.ball.radius, width = b.beam.properties.width;
  const std::string load = " under the ball's weight W = " + io::three_digits(b.weight()) + " N";
  if (!(std::isfinite(a) && a > 0.0)) return;
  if (a / r > 0.1)
    b.ball.origin(b.ball.radius)
        .refuse("the Hertz contact radius a = " + io::three_digits(a) + " m" + load + " is " + io::three_digits(a / r) +
                " R; Hertz theory needs a/R <= 0.1 (a softer or heavier ball than the theory covers)");
  if (2.0 * a > width)
    b.ball.origin(b.ball.radius)
        .refuse("the Hertz contact width 2a = " + io::three_digits(2.0 * a) + " m" + load + " exceeds the beam width " +
                io::three_digits(width) + " m (a point contact on a beam; radius and width are in m)");
  if (a / r > 0.03)
    warnings.push_back(b.ball.origin(b.ball.radius).where + ": the Hertz contact radius a = " + io::three_digits(a) +
                       " m is " + io::three_digits(a / r) +
                       " R; Hertz theory loses accuracy above a/R of a few per cent");
  else if (2.0 * a > 0.2 * width)
    warnings.push_back(
        b.ball.origin(b.ball.radius).where + ": the Hertz contact width 2a = " + io::three_digits(2.0 * a) + " m is " +
        io::three_digits(2.0 * a / width) + " of the beam width; the point contact assumes a narrow contact");
}

// The linear beam holds for deflections small against its thickness; the largest static deflection
// under the ball's weight along the traverse (exact flexibility of the modal beam, B7-B8).
void check_deflection(const BallOnBeamSettings& b, std::vector<std::string>& warnings) {
  const double x0 = b.model.traverse.x_start, x1 = b.model.traverse.x_end, t = b.beam.properties.thickness;
  double w = 0.0;
  for (int i = 0; i <= 20; ++i) {
    const double x = x0 + (x1 - x0) * i / 20.0;
    w = std::max(w, std::abs(b.model.beam.static_flexibility(x, x)) * b.weight());
  }
  if (!std::isfinite(w)) return;
  const std::string what = "the beam's static deflection under the ball's weight W = " + io::three_digits(b.weight()) +
                           " N reaches " + io::three_digits(w) + " m, ";
  if (w > t)
    b.ball.origin(b.ball.radius)
        .refuse(what + "more than the beam thickness " + io::three_digits(t) +
                " m; linear beam theory needs deflections small against the thickness (radius in m?)");
  if (w > 0.1 * t)
    warnings.push_back(b.ball.origin(b.ball.radius).where + ": " + what + io::three_digits(w / t) +
                       " of the beam thickness; linear beam theory assumes small deflections");
  const double length = b.beam.properties.length;
  if (t > 0.1 * length)
    warnings.push_back(b.beam.origin(b.beam.properties.thickness).where + ": the beam is " +
                       io::three_digits(t / length) +
                       " of its span thick; Euler-Bernoulli theory (no shear, no rotary inertia) needs a slender beam");
}

// The modes kept against the band the output reports: resonances above the highest kept mode are
// missing from the response (the static correction adds their flexibility only).
void check_modes(const BallOnBeamSettings& b, std::vector<std::string>& warnings) {
  const auto& m = b.model.beam;
  if (m.modes() <= 0) return;
  const double top = m.frequency(m.modes() - 1), nyquist = b.model.sample_rate / 2.0;
  const double band = std::min(b.band_max, nyquist);
  if (top < band)
    warnings.push_back((b.beam.selection.count > 0 ? b.beam.origin(b.beam.selection.count)
                                                   : b.beam.origin(b.beam.selection.max_frequency))
                           .where +
                       ": the highest kept mode (" + io::three_digits(top) + " Hz) lies below the band's top " +
                       io::three_digits(band) + " Hz; the response above it has no resonances");
  if (m.frequency(0) > nyquist)
    warnings.push_back(b.sample_rate_origin.where + ": the first beam mode (" + io::three_digits(m.frequency(0)) +
                       " Hz) lies above the Nyquist frequency " + io::three_digits(nyquist) +
                       " Hz; the output holds no resonance");
}

// The roughness's wavenumbers k (rad/m) excite f = v k / (2 pi): where they stop, the band above
// has no excitation from the roughness; a speed beyond what a rolling ball reaches is a unit slip.
void check_roughness(const BallOnBeamSettings& b, std::vector<std::string>& warnings) {
  const double v = b.model.traverse.speed;
  if (v > 100.0)
    b.ball.origin(b.ball.speed)
        .refuse("a rolling ball at " + io::three_digits(v) + " m/s (" + io::three_digits(v * 3.6) +
                " km/h) is beyond any rig; the speed is in m/s");
  if (v > 30.0)
    warnings.push_back(b.ball.origin(b.ball.speed).where + ": a rolling speed of " + io::three_digits(v) + " m/s (" +
                       io::three_digits(v * 3.6) + " km/h) is unusual for a ball on a beam; the speed is in m/s");
  const double k_max = b.texture_psd.support_max, k_min = b.texture_psd.support_min;
  const double band = std::min(b.band_max, b.model.sample_rate / 2.0);
  if (std::isfinite(k_max) && k_max > 0.0 && v * k_max / (2.0 * M_PI) < band)
    warnings.push_back(b.ball.origin(b.ball.speed).where + ": the roughness spectrum ([texture]) stops at wavelength " +
                       io::three_digits(2.0 * M_PI / k_max) + " m, which at " + io::three_digits(v) +
                       " m/s excites up to " + io::three_digits(v * k_max / (2.0 * M_PI)) +
                       " Hz; the bands above it up to " + io::three_digits(band) +
                       " Hz get no excitation from the roughness");
  if (k_min > 0.0 && v * k_min / (2.0 * M_PI) > band)
    warnings.push_back(b.ball.origin(b.ball.speed).where +
                       ": the roughness spectrum ([texture]) starts at wavelength " +
                       io::three_digits(2.0 * M_PI / k_min) + " m, which at " + io::three_digits(v) + " m/s excites " +
                       io::three_digits(v * k_min / (2.0 * M_PI)) + " Hz and above, beyond the band's top " +
                       io::three_digits(band) + " Hz");
}

// The line roughness's rms height up to the band limit (variance = int G dk, on a log grid).
double line_rms(const BallOnBeamSettings& b) {
  const double k0 = std::max(b.psd.support_min, 2.0 * M_PI / b.beam.properties.length);
  const double k1 = std::min({b.psd.support_max, b.band_limit_wavenumber, M_PI / b.spacing});
  if (!(k1 > k0)) return 0.0;
  const int n = 400;
  double variance = 0.0, previous = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double k = k0 * std::pow(k1 / k0, i / static_cast<double>(n)), g = b.psd(k) * k;  // G dk = G k dln k
    if (i > 0) variance += 0.5 * (g + previous) * std::log(k1 / k0) / n;
    previous = g;
  }
  return std::sqrt(variance);
}

// Roughness as tall as the static compression under the ball's weight lifts the ball off: the
// result then describes impacts, which a reviewer would ask about before anything else.
void check_roughness_height(const BallOnBeamSettings& b, std::vector<std::string>& warnings) {
  if (b.path_law() || b.blocked_solver() || !(b.static_compression > 0.0)) return;
  double rms = 0.0;
  try {
    rms = line_rms(b);
  } catch (const std::exception&) {  // a PSD table without extension: its range is checked elsewhere
    return;
  }
  if (rms > 0.5 * b.static_compression)
    warnings.push_back(b.roughness_origin.where + ": the roughness's rms height " + io::three_digits(rms) +
                       " m (up to the band limit) is " + io::three_digits(rms / b.static_compression) +
                       " of the static compression " + io::three_digits(b.static_compression) +
                       " m under the ball's weight: expect loss of contact (the result says how often)");
}

}  // namespace

std::vector<std::string> check_ball_on_beam_plausibility(const BallOnBeamSettings& b) {
  std::vector<std::string> warnings;
  check_contact(b, warnings);
  check_deflection(b, warnings);
  check_modes(b, warnings);
  check_roughness(b, warnings);
  check_roughness_height(b, warnings);
  return warnings;
}

std::string loss_of_contact_warning(double share, bool linearised) {
  if (!(share > 0.0)) return "";
  const std::string pct = io::three_digits(100.0 * share) + " %";
  if (linearised)  // unmeasured (a fit's evaluation): no size to give, so no claim either way
    return "the ball lost contact " + pct + " of the time ([contact] law = linearised assumes a closed contact)";
  if (share > loss_of_contact_warning_share)
    return "the ball lost contact " + pct + " of the time (more than " +
           io::three_digits(100.0 * loss_of_contact_warning_share) +
           " %): the response is dominated by impacts, which the [contact] law models";
  return "";
}

}  // namespace rollspec::scenes
