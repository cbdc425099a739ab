#include "src/scenes/ball_on_beam/ball_on_beam_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <utility>

#include "kernels/beam/path_contact_table.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::scenes {

ResolvedContact contact_from_settings(const BallOnBeamSettings& b) {
  ResolvedContact c;
  c.law = b.model.contact;
  c.static_compression = b.static_compression;
  c.contact_stiffness = b.contact_stiffness;
  c.line_psd = b.line_psd;
  return c;
}

beam::BallOnBeamModel resolved_model(const BallOnBeamSettings& b, const ResolvedContact& c) {
  beam::BallOnBeamModel m = b.model;
  m.contact = c.law;
  return m;
}

namespace {
// [stiffness] table_shift: the mean curves moved by `shift` standard errors of the mean over the table's
// N surfaces, sigma_j / sqrt(N) (kernels/spectral/README.md D-28, T-1); the same bits for shift 0.
stiffness::StiffnessTable shifted_table(const stiffness::StiffnessTable& t, double shift) {
  if (shift == 0.0) return t;
  stiffness::StiffnessTable s = t;
  const double per_std = shift / std::sqrt(static_cast<double>(std::max<std::int64_t>(t.realisations, 1)));
  for (std::size_t j = 0; j < s.approach.size(); ++j) {
    s.force_mean[j] += per_std * t.force_std[j];
    s.stiffness_mean[j] += per_std * t.stiffness_std[j];
  }
  return s;
}
}  // namespace

void take_stiffness_table(const BallOnBeamSettings& b, const stiffness::StiffnessTable& table, ResolvedContact& c) {
  const stiffness::StiffnessTable t = shifted_table(table, b.stiffness.table_shift);
  for (std::size_t j = 1; b.stiffness.table_shift != 0.0 && j < t.approach.size(); ++j)
    if (!(t.force_mean[j] > t.force_mean[j - 1]))
      b.stiffness.origin(b.stiffness.table_shift)
          .refuse("the shifted table's mean force does not rise with the approach at " + std::to_string(t.approach[j]) +
                  " m; shift it less");
  c.law.compression = t.approach;
  if (c.law.kind == beam::ContactLawKind::table) {
    c.law.values = t.force_mean;
  } else {  // seed 001 Eq. 7 literally: k_c(delta) from the table's stiffness, F = k_c(delta) delta
    c.law.values = t.stiffness_mean;
    c.law.values[0] = t.stiffness_mean[1];
  }
  c.static_compression = t.approach_at(b.weight());
  if (!(c.static_compression > 0.0))
    b.stiffness.origin(b.stiffness.approach_max)
        .refuse("the table's largest force " + std::to_string(t.force_mean.back()) +
                " N does not reach the ball's weight; raise approach_max");
  c.contact_stiffness = t.stiffness_at(b.weight());
  check_contact_resolution(b, c.contact_stiffness);
}

void take_path_table(const BallOnBeamSettings& b, const stiffness::PathTableData& t, ResolvedContact& c) {
  beam::PathContactData d{t.position, t.approach, t.first_contact, t.force, {}};
  for (double r : t.rows) d.rows.push_back(static_cast<std::size_t>(r));
  const auto every = static_cast<std::size_t>(b.path_table.rows_every);
  if (every > 1) {  // each position must keep a row: refused with the table's fewest rows
    std::size_t fewest = d.approach.size();
    for (std::size_t r : d.rows) fewest = std::min(fewest, r);
    if (fewest < every)
      b.path_table.origin(b.path_table.rows_every)
          .refuse("reads no row at a position whose table holds only " + std::to_string(fewest) +
                  " rows; allowed: 1 .. " + std::to_string(fewest));
    d = beam::thinned_rows(d, every);
  }
  d.interpolation = b.path_table.interpolation == study::PathInterpolation::cubic ? beam::PathInterpolation::cubic
                                                                                  : beam::PathInterpolation::linear;
  const bool cubic = d.interpolation == beam::PathInterpolation::cubic;
  const auto positions_every = static_cast<std::size_t>(b.path_table.positions_every);
  if (positions_every > 1) d = beam::thinned_positions(d, positions_every);
  c.law.path = std::make_shared<const beam::PathContactTable>(std::move(d));
  c.law.path_origin = b.model.traverse.x_start;
  // B46's start: with B45b, the slope over [0, a/2] whatever the step; B45 keeps its first interval's
  // chord, the point laws' rule (line = strip starts the same way).
  if (cubic) c.law.path_start_width = b.contact_half_width;
  const std::vector<double> static_approach = beam::path_static_approaches(*c.law.path, b.weight());
  c.static_compression = beam::path_table_static_approach(static_approach);
  if (!t.check_position.empty())
    c.path_check = std::make_shared<const PathTableCheck>(
        path_table_check(*c.law.path, b.weight(), static_approach, t.check_position, t.check_approach));
}

void take_strip_line(const BallOnBeamSettings& b, const stiffness::EquivalentRoughnessTable& t, ResolvedContact& c) {
  c.strip_line = beam::UniformSamples{b.model.traverse.x_start, t.position.at(1) - t.position.at(0), t.height};
}

// ER-7: F'(delta) = F(rho delta) carries the weight at delta_W / rho with the strips' mean contact
// stiffness rho k(delta_W): a rough strip is softer than the smooth contact h_eq alone assumes.
double take_equivalent_stiffness(const BallOnBeamSettings& b, const stiffness::EquivalentRoughnessTable& t,
                                 ResolvedContact& c) {
  if (!b.equivalent_stiffness) return 0.0;
  const double rho = t.stiffness_ratio();
  beam::ContactLaw& law = c.law;
  switch (law.kind) {
    case beam::ContactLawKind::hertz:
      law.effective_modulus *= std::pow(rho, 1.5);  // (4/3) E* sqrt(R) (rho delta)^(3/2)
      break;
    case beam::ContactLawKind::table:
      for (double& x : law.compression) x /= rho;
      break;
    case beam::ContactLawKind::literal_stiffness:  // k_c'(delta) delta = rho k_c(rho delta) delta
      for (double& x : law.compression) x /= rho;
      for (double& v : law.values) v *= rho;
      break;
    default:
      return 0.0;
  }
  c.static_compression /= rho;
  return rho;
}

// filter = solver: the line is synthesised from the strip-mean PSD of h_eq (ER-2), band-limited
// (B40), no patch average and so no B40a compensation. Below the table's third bin k1 (bins 1 and
// 2 of a Hann segment hold the leakage of waves longer than the segment, as for the blocked force)
// the line takes the first-order theory's shape, G_eq of ER-5 (iso2d, Eq. 38), times an even factor
// that is 1 at k = 0 and meets the table at k1: G_eq(k) (1 + (rho1 - 1) (k/k1)^2), rho1 =
// G_table(k1) / G_eq(k1). At long waves h_eq is the flat-punch average of ER-3 exactly, which on an
// isotropic surface also averages the roughness across the path (G_eq(0) < G(0) where the surface
// has power at wavelengths below 2a). A PSD without an isotropic form falls back to the raw line
// G_raw (h_eq -> h, as for corrugation uniform across the path).
void take_equivalent_roughness_psd(const BallOnBeamSettings& b, const stiffness::EquivalentRoughnessTable& t,
                                   ResolvedContact& c) {
  auto table = std::make_shared<const stiffness::EquivalentRoughnessTable>(t);
  c.equivalent = table;
  texture::Psd low = b.texture_psd;
  try {
    low = iso2d_line_psd(b);
  } catch (const std::exception&) {  // no isotropic form: the raw line's shape
  }
  const std::size_t anchor = std::min<std::size_t>(3, t.psd_wavenumber.size() - 1);
  const double k1 = t.psd_wavenumber.size() > 1 ? t.psd_wavenumber[anchor] : 0.0;
  texture::Psd p;
  p.density = [table, low, k1](double k) {
    if (k >= k1 || !(k > 0.0)) return table->psd_at(k);
    const double g1 = low(k1);
    if (!(g1 > 0.0)) return table->psd_at(k);
    const double r = k / k1;
    return low(k) * (1.0 + (table->psd_at(k1) / g1 - 1.0) * r * r);
  };
  p.support_min = b.texture_psd.support_min;
  p.support_max = t.psd_wavenumber.empty() ? 0.0 : t.psd_wavenumber.back();
  p.description = "PSD of the equivalent roughness h_eq on " + std::to_string(t.position.size()) + " positions x " +
                  std::to_string(static_cast<long long>(t.strips)) + " strips (kernels/contact ER-2)";
  for (std::size_t j = 1; j < t.psd_wavenumber.size(); ++j) p.breakpoints.push_back(t.psd_wavenumber[j]);
  c.line_psd = std::isfinite(b.band_limit_wavenumber) ? texture::band_limited(std::move(p), b.band_limit_wavenumber)
                                                      : std::move(p);
}

// The contact solver's blocked force (seed 002 §4.2): k0 from the table, F0(t) synthesised per
// realisation from the table's PSD (the excitation).
void take_blocked_force(const BallOnBeamSettings& b, const stiffness::BlockedForceTable& t, ResolvedContact& c) {
  c.blocked = t;
  c.law.k0 = c.blocked.k0;
  c.static_compression = b.weight() / c.blocked.k0;
  c.contact_stiffness = c.blocked.k0;
  check_contact_resolution(b, c.contact_stiffness);
}

// F0 PSD along the path: the table's, and at long wavelengths, where the ball follows the
// texture (F0 = W + k0 h), the texture's shape scaled to the table at its third bin: bins 1 and 2
// of a Hann-windowed segment hold the leakage of waves longer than the segment (the strip is finite).
namespace {
constexpr std::size_t kAnchorBin = 3;  // the F0 table's first bin clear of the segment's own leakage
}  // namespace

double blocked_force_psd(const BallOnBeamSettings& b, const stiffness::BlockedForceTable& t, double k) {
  if (k > b.band_limit_wavenumber) return 0.0;  // B40, as the texture
  const std::size_t anchor = std::min<std::size_t>(kAnchorBin, t.psd_wavenumber.size() - 1);
  const double k1 = t.psd_wavenumber.size() > 1 ? t.psd_wavenumber[anchor] : 0.0;
  if (k >= k1 || !(k > 0.0)) return t.psd_at(k);
  const double g1 = b.psd(k1);
  return g1 > 0.0 ? t.psd_at(k1) * b.psd(k) / g1 : t.psd_at(k);
}

// G_t(f) = 2 pi G_k(2 pi f / v) / v (D-2).
double blocked_force_time_psd(const BallOnBeamSettings& b, const stiffness::BlockedForceTable& t, double f) {
  const double v = b.model.traverse.speed;
  return 2.0 * M_PI * blocked_force_psd(b, t, 2.0 * M_PI * f / v) / v;
}

namespace {
// Each result band's estimated error of a checked strip table's PSD (BF-9c), at k = 2 pi f / v (D-2).
template <class Table>
std::vector<double> band_errors(const BallOnBeamSettings& b, const Table& t, const std::vector<spectral::Band>& bands) {
  const double to_k = 2.0 * M_PI / b.model.traverse.speed;
  std::vector<double> out;
  for (const spectral::Band& band : bands)
    out.push_back(t.band_error_db(band.lower * to_k, band.upper * to_k, kAnchorBin));
  return out;
}
}  // namespace

std::vector<double> blocked_force_band_error_db(const BallOnBeamSettings& b, const stiffness::BlockedForceTable& t,
                                                const std::vector<spectral::Band>& bands) {
  return band_errors(b, t, bands);
}

std::vector<double> equivalent_roughness_band_error_db(const BallOnBeamSettings& b,
                                                       const stiffness::EquivalentRoughnessTable& t,
                                                       const std::vector<spectral::Band>& bands) {
  return band_errors(b, t, bands);
}

std::vector<double> path_table_band_error_db(const BallOnBeamSettings& b, const PathTableCheck& t,
                                             const std::vector<spectral::Band>& bands) {
  return band_errors(b, t, bands);
}

std::string blocked_force_resolution_warning(const BallOnBeamSettings& b, const stiffness::BlockedForceGeometry& g) {
  const double segment = static_cast<double>(std::min(g.segment, g.positions)) * static_cast<double>(g.step) * g.cell;
  const double wavelength = segment / static_cast<double>(kAnchorBin), v = b.model.traverse.speed;
  const double f = v / wavelength;
  if (!(f > b.band_min)) return {};
  const std::string text = io::formatted(
      "[blocked_force] segment: F0's PSD is the contact solver's own from its Welch bin %zu up, wavelength "
      "%.3g mm, i.e. %.4g Hz at [ball] speed = %g m/s; the bands from [spectrum] band_min = %g Hz to there "
      "take the texture PSD's shape scaled to that bin (the strip's segment of %.3g mm resolves no longer "
      "wave). A longer [blocked_force] segment (and strip_length, for as many segments) resolves them",
      kAnchorBin, wavelength * 1e3, f, v, b.band_min, segment * 1e3);
  return text;
}

}  // namespace rollspec::scenes
