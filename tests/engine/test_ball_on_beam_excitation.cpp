// Scene ball-on-beam's pieces apart from the scene: the contact the table stages resolve from the
// const settings, and the excitation of each kind, which must draw the study's Philox streams and
// give the same input for a realisation id on every thread.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/contact/hertz.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_contact.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_excitation.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"
#include "src/scenes/scene.hpp"
#include "tests/engine/study_from_text.hpp"
#include "src/texture/texture_keys.hpp"

using namespace rollspec;
using scenes::BallOnBeamSettings;
using scenes::ResolvedContact;

namespace {

// A short traverse on the default beam; `overrides` pick the contact model.
BallOnBeamSettings settings(const std::vector<std::string>& overrides) {
  const study::Study s =
      test::study_from_text("/tmp/rollspec_excitation.ini",
                            "[study]\nscene = ball-on-beam\nrealisations = 2\nseed = 7\n[ball]\nstart "
                            "= 0.1\nend = 0.11\n[spectrum]\nsegment = 128\n",
                            overrides);
  return scenes::read_ball_on_beam_settings(scenes::BallOnBeamSections::parse(s));
}

std::shared_ptr<const texture::LineTextureGenerator> lines_of(const BallOnBeamSettings& b, const ResolvedContact& c) {
  return texture_io::line_generator(b.line_keys, c.line_psd, b.spacing, b.line_samples);
}

// Realisation id's line as the scene drew it before the excitation had its own type: the roughness
// streams into the generator, patch-averaged where the filter is patch.
beam::UniformSamples reference_line(const BallOnBeamSettings& b, const texture::LineTextureGenerator& lines,
                                    std::uint64_t id) {
  std::vector<double> phase(lines.harmonics()), amp(lines.harmonics()), h(b.line_samples);
  rng::PhiloxStream(b.seed, id, rng::Stream::roughness_phase).uniform_open(phase.data(), phase.size());
  rng::PhiloxStream(b.seed, id, rng::Stream::roughness_amplitude).uniform_open(amp.data(), amp.size());
  lines.generate(phase.data(), amp.data(), h.data());
  beam::UniformSamples line{0.0, b.spacing, h};
  return b.patch_half_width > 0.0 ? beam::contact_patch_average(line, b.patch_half_width) : line;
}

beam::Realisation fill(const scenes::BallOnBeamExcitation& e, std::uint64_t id, int thread) {
  beam::Realisation r;
  e.fill(id, thread, r);
  return r;
}

}  // namespace

TEST_CASE("resolved contact: from the hertz law it is the settings' law, and the model carries it") {
  const BallOnBeamSettings b = settings({"contact.law=hertz"});
  const ResolvedContact c = scenes::contact_from_settings(b);
  CHECK(c.law.kind == beam::ContactLawKind::hertz);
  CHECK(c.law.effective_modulus == b.model.contact.effective_modulus);
  CHECK(c.law.radius == b.model.contact.radius);
  CHECK(c.law.damping == b.model.contact.damping);
  const double e_star = c.law.effective_modulus, r = c.law.radius;
  // The compression at which Hertz's force carries the weight (the inverse of the approach's formula).
  CHECK(contact::hertz::force_at_approach(r, e_star, c.static_compression) ==
        doctest::Approx(b.weight()).epsilon(1e-14));
  for (double k : {10.0, 1e3, 1e5}) CHECK(c.line_psd(k) == b.line_psd(k));
  CHECK(c.strip_line.values.empty());
  const beam::BallOnBeamModel m = scenes::resolved_model(b, c);
  CHECK(m.contact.effective_modulus == e_star);
  CHECK(m.traverse.x_start == 0.1);
  CHECK(m.sensors == b.model.sensors);
}

TEST_CASE("resolved contact: ER-7 stretches the Hertz law by 1/rho, which still carries the weight") {
  const BallOnBeamSettings b =
      settings({"contact.law=hertz", "contact.filter=solver", "equivalent_roughness.stiffness=strip"});
  REQUIRE(b.equivalent_stiffness);
  ResolvedContact c = scenes::contact_from_settings(b);
  stiffness::EquivalentRoughnessTable t;
  t.smooth_stiffness = 2e8;
  t.stiffness = {1e8, NAN, 1.2e8};  // rho = 0.55 over the sampled positions
  const double rho = scenes::take_equivalent_stiffness(b, t, c);
  CHECK(rho == doctest::Approx(0.55).epsilon(1e-15));
  CHECK(c.law.effective_modulus == doctest::Approx(b.model.contact.effective_modulus * std::pow(0.55, 1.5)));
  CHECK(c.static_compression == doctest::Approx(b.static_compression / 0.55));
  const double force = contact::hertz::force_at_approach(c.law.radius, c.law.effective_modulus, c.static_compression);
  CHECK(force == doctest::Approx(b.weight()).epsilon(1e-12));
  const BallOnBeamSettings law =
      settings({"contact.law=hertz", "contact.filter=solver", "equivalent_roughness.stiffness=law"});
  ResolvedContact unchanged = scenes::contact_from_settings(law);
  CHECK(scenes::take_equivalent_stiffness(law, t, unchanged) == 0.0);
  CHECK(unchanged.law.effective_modulus == law.model.contact.effective_modulus);
}

TEST_CASE("excitation: the synthesised line is the study's roughness streams, the same on every thread") {
  const BallOnBeamSettings b = settings({"contact.law=hertz", "contact.filter=patch"});
  REQUIRE(b.patch_half_width > 0.0);
  const ResolvedContact c = scenes::contact_from_settings(b);
  const auto lines = lines_of(b, c);
  const auto e = scenes::make_ball_on_beam_excitation(b, c, lines, 2);
  const beam::Realisation r = fill(*e, 5, 0);
  const beam::UniformSamples want = reference_line(b, *lines, 5);
  CHECK(r.blocked_force.values.empty());
  CHECK(r.roughness.origin == want.origin);
  CHECK(r.roughness.step == want.step);
  CHECK(r.roughness.values == want.values);
  CHECK(fill(*e, 5, 1).roughness.values == want.values);
  CHECK(fill(*e, 5, 0).roughness.values == want.values);  // the workspace keeps nothing between realisations
  CHECK(fill(*e, 6, 0).roughness.values != want.values);
}

TEST_CASE("excitation: the linear spring's blocked force is W + k0 h along the traverse (D-11)") {
  const BallOnBeamSettings b = settings({"contact.law=linearised", "contact.filter=none"});
  const ResolvedContact c = scenes::contact_from_settings(b);
  const auto lines = lines_of(b, c);
  const auto e = scenes::make_ball_on_beam_excitation(b, c, lines, 1);
  const beam::Realisation r = fill(*e, 3, 0);
  const beam::UniformSamples h = reference_line(b, *lines, 3);
  const auto first = static_cast<std::size_t>(std::floor(0.1 / b.spacing));
  CHECK(r.roughness.values.empty());
  REQUIRE(r.blocked_force.values.size() == h.values.size() - first);
  CHECK(r.blocked_force.step == b.spacing / b.model.traverse.speed);
  CHECK(r.blocked_force.origin <= 0.0);
  CHECK(r.blocked_force.origin > -r.blocked_force.step);
  for (std::size_t i = 0; i < r.blocked_force.values.size(); i += 97)
    CHECK(r.blocked_force.values[i] == b.weight() + c.law.k0 * h.values[first + i]);
}

TEST_CASE("excitation: the solver's blocked force is drawn from its table's PSD, mean W, per id") {
  const BallOnBeamSettings b = settings({"contact.law=linearised", "contact.blocked_force=solver"});
  ResolvedContact c = scenes::contact_from_settings(b);
  stiffness::BlockedForceTable t;
  t.k0 = 2e7;
  t.approach = b.weight() / t.k0;
  t.psd_wavenumber = {0.0, 1e3, 2e3, 4e3, 8e3, 1.6e4};
  t.psd = {1e-6, 1e-6, 1e-6, 5e-7, 2e-7, 1e-7};
  scenes::take_blocked_force(b, t, c);
  CHECK(c.law.k0 == 2e7);
  CHECK(c.static_compression == b.weight() / 2e7);
  const auto e = scenes::make_ball_on_beam_excitation(b, c, nullptr, 2);
  const beam::Realisation r = fill(*e, 4, 0);
  CHECK(r.roughness.values.empty());
  CHECK(r.blocked_force.origin == 0.0);
  CHECK(r.blocked_force.step == b.integration_step());
  const std::vector<double>& f = r.blocked_force.values;
  REQUIRE(static_cast<double>(f.size()) * b.integration_step() >= beam::traverse_duration(b.model.traverse));
  // No power at f = 0: over the synthesis period the mean is the weight.
  const double mean = std::accumulate(f.begin(), f.end(), 0.0) / static_cast<double>(f.size());
  CHECK(mean == doctest::Approx(b.weight()).epsilon(1e-9));
  double var = 0.0;
  for (double x : f) var += (x - mean) * (x - mean);
  CHECK(var > 0.0);
  CHECK(fill(*e, 4, 1).blocked_force.values == f);
  CHECK(fill(*e, 5, 0).blocked_force.values != f);
}

TEST_CASE("excitation: line = strip gives the strip's h_eq every realisation; law = path gives nothing") {
  const BallOnBeamSettings b =
      settings({"contact.law=hertz", "contact.filter=solver", "equivalent_roughness.line=strip"});
  ResolvedContact c = scenes::contact_from_settings(b);
  stiffness::EquivalentRoughnessTable t;
  t.position = {0.0, 2e-5, 4e-5};
  t.height = {1e-7, -2e-7, 3e-7};
  scenes::take_strip_line(b, t, c);
  const auto e = scenes::make_ball_on_beam_excitation(b, c, nullptr, 1);
  for (std::uint64_t id : {0u, 9u}) {
    const beam::Realisation r = fill(*e, id, 0);
    CHECK(r.roughness.origin == 0.1);
    CHECK(r.roughness.step == 2e-5);
    CHECK(r.roughness.values == t.height);
    CHECK(r.blocked_force.values.empty());
  }
  const BallOnBeamSettings p = settings({"contact.law=path"});
  const auto path = scenes::make_ball_on_beam_excitation(p, scenes::contact_from_settings(p), nullptr, 1);
  const beam::Realisation r = fill(*path, 2, 0);
  CHECK(r.roughness.values.empty());
  CHECK(r.blocked_force.values.empty());
}
