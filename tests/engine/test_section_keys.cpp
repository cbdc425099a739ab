// One declaration per key (src/study/sections/section_keys.hpp): the KeySpecs it gives, the values read into
// the fields, and each key's text, origin and set flag found again by its field, on a real study.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/contact_section.hpp"
#include "src/study/sections/equivalent_roughness_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/rolling_world_sections.hpp"
#include "src/study/sections/spectrum_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "tests/engine/study_from_text.hpp"

using namespace rollspec;
using test::message_of;

namespace {
const test::SceneStudies ball_on_beam{"/tmp/rollspec_section_keys.ini", "ball-on-beam", 2, 1};
}  // namespace

TEST_CASE("section keys: the KeySpecs in declaration order, with range, unit and default") {
  const auto k = study::BallSection::keys();
  REQUIRE(k.size() == 8);
  CHECK(k[0].full_name() == "ball.radius");
  CHECK(k[0].unit == "m");
  CHECK(k[0].default_value == std::string("0.02"));
  CHECK((k[0].min == 0.0 && !k[0].min_inclusive && k[0].max_inclusive));
  CHECK(k[3].full_name() == "ball.poisson");
  CHECK((k[3].min == -1.0 && k[3].max == 0.5 && !k[3].min_inclusive && !k[3].max_inclusive));
  CHECK(k[7].full_name() == "ball.gravity");
  // A scene's subset with its own docs: stiffness's ball has no traverse.
  const auto solid = study::BallSection::solid_keys();
  REQUIRE(solid.size() == 5);
  CHECK(solid[4].full_name() == "ball.gravity");
  CHECK(solid[1].doc == "ball density (weight = 4/3 pi R^3 rho g)");
  // skip_start is each scene's: not among the shared keys, its doc and default the scene's.
  for (const auto& s : study::SpectrumSection::keys()) CHECK(s.key != "skip_start");
  const auto skip = study::SpectrumSection::skip_start_key("doc", "0.5");
  CHECK((skip.full_name() == "spectrum.skip_start" && skip.doc == "doc" && skip.default_value == "0.5"));
}

TEST_CASE("section keys: values into the fields (nested ones too), text and origin by field") {
  const auto s = ball_on_beam("[ball]\nradius = 0.01\n[beam]\nthickness = 5e-3\n", {"contact.filter=none"});
  const auto ball = study::BallSection::parse(s);
  CHECK(ball.radius == 0.01);
  CHECK(ball.speed == 1.0);  // the default
  CHECK(ball.value_text(ball.radius) == "0.01");
  CHECK(ball.was_set(ball.radius));
  CHECK_FALSE(ball.was_set(ball.speed));
  CHECK(ball.origin(ball.radius).where == "/tmp/rollspec_section_keys.ini:6: [ball] radius = 0.01");
  CHECK(ball.origin(ball.speed).where == "/tmp/rollspec_section_keys.ini (default): [ball] speed = 1");
  const auto beam = study::ModalBeamSection::parse(s);
  CHECK(beam.properties.thickness == 5e-3);
  CHECK(beam.origin(beam.properties.thickness).where == "/tmp/rollspec_section_keys.ini:8: [beam] thickness = 0.005");
  const auto contact = study::ContactSection::parse(s);
  CHECK(contact.filter == study::ContactFilter::none);
  CHECK(contact.was_set(contact.filter));
  CHECK(contact.origin(contact.filter).where == "command line (--set): [contact] filter = none");
  // A copy keeps its keys' origins (they are found relative to the section).
  const study::BallSection copy = ball;
  CHECK(copy.origin(copy.radius).where == ball.origin(ball.radius).where);
  // A field no key was read into is a programming error, not a study's.
  CHECK_THROWS_AS((void)ball.origin(ball.mass()), std::logic_error);
}

TEST_CASE("section keys: --set texts from the declaration, checks at the key") {
  CHECK(study::BlockedForceSection::leave_out_setting(3) == "blocked_force.leave_out=3");
  CHECK(study::EquivalentRoughnessSection::leave_out_setting(0) == "equivalent_roughness.leave_out=0");
  CHECK(study::ContactSection::loss_setting(study::ContactLoss::closed) == "contact.loss=closed");
  const std::string m = message_of([] {
    (void)study::EquivalentRoughnessSection::parse(ball_on_beam("[equivalent_roughness]\nstrips = 2\nleave_out = 2\n"));
  });
  CHECK(m ==
        "/tmp/rollspec_section_keys.ini:7: [equivalent_roughness] leave_out = 2: leaves out a strip the table does not "
        "have; allowed: -1 .. 1 ([equivalent_roughness] strips = 2)");
}

TEST_CASE("section keys: a key read only when an earlier one asks for it") {
  const auto none = test::study_from_text("/tmp/rollspec_section_keys.ini",
                                          "[study]\nscene = rolling-beam\nrealisations = 1\nseed = 1\n"
                                          "[imposed]\ntimes = 0, 1\nvalues = 0\n");
  const auto m = study::ImposedSection::parse(none);  // node = none: times and values are not read
  CHECK((m.node == study::ImposedNode::none && m.times.empty() && m.key_values().size() == 2));
  const auto first = test::study_from_text("/tmp/rollspec_section_keys.ini",
                                           "[study]\nscene = rolling-beam\nrealisations = 1\nseed = 1\n"
                                           "[imposed]\nnode = first\ntimes = 0, 1\nvalues = 0, 2e-3\n");
  const auto f = study::ImposedSection::parse(first);
  CHECK((f.times.size() == 2 && f.values[1] == 2e-3));
}

TEST_CASE("section keys: a key named by its member, nested members too; a member no key reads is refused") {
  using study::BallSection;
  using study::ModalBeamSection;
  CHECK(BallSection::key(&BallSection::radius) == "ball.radius");
  CHECK(BallSection::key(&BallSection::gravity) == "ball.gravity");
  CHECK(ModalBeamSection::key(&ModalBeamSection::poisson) == "beam.poisson");
  CHECK(ModalBeamSection::key(&ModalBeamSection::properties, &beam::BeamProperties::thickness) == "beam.thickness");
  CHECK(ModalBeamSection::key(&ModalBeamSection::damping, &beam::ModalDamping::loss_factor) == "beam.loss_factor");
  // A member the section derives (rough, from surface) is no key's: refused, not named after a neighbour.
  CHECK(study::StiffnessSection::key(&study::StiffnessSection::surface) == "stiffness.surface");
  CHECK_THROWS_AS(study::StiffnessSection::key(&study::StiffnessSection::rough), std::logic_error);
}
