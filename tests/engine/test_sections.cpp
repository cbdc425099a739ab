// Typed study sections (src/study/sections): parsed once from a Study, the same values and the same
// file:line messages as the string reads they replace.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "kernels/contact/geometry.hpp"
#include "src/error.hpp"
#include "src/scenes/scene.hpp"
#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/modal_beam_section.hpp"
#include "src/study/sections/path_table_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/strip_surface_section.hpp"
#include "tests/engine/study_from_text.hpp"
#include "src/texture/texture_keys.hpp"

using namespace rollspec;
using test::message_of;

namespace {
const test::SceneStudies ball_on_beam{"/tmp/rollspec_sections.ini", "ball-on-beam", 2, 1};

}  // namespace

TEST_CASE("ball section: weight and E* as the scene derives them") {
  const auto s = ball_on_beam("[ball]\nradius = 0.01\ndensity = 7800\ngravity = 9.8\n");
  const auto ball = study::BallSection::parse(s);
  const auto beam = study::ModalBeamSection::parse(s);
  // A 20 mm steel ball: 32.6726 g (4/3 pi (1 cm)^3 = 4.18879 cm^3 at 7.8 g/cm^3, to 30 digits in decimal), 0.320191 N.
  CHECK(ball.mass() == doctest::Approx(0.03267256359733384968).epsilon(1e-15));
  CHECK(ball.weight() == doctest::Approx(0.3201911232538717269).epsilon(1e-15));
  CHECK(ball.effective_modulus(beam.properties.youngs_modulus, beam.poisson) ==
        contact::effective_modulus(210e9, 0.3, 210e9, 0.3));
}

TEST_CASE("ball section: a later check names [ball] end where the study set it") {
  const auto s = ball_on_beam("[ball]\nend = 0.5\n");
  const auto ball = study::BallSection::parse(s);
  const std::string m = message_of([&] { ball.origin(ball.end).refuse("lies beyond the span [0, length]"); });
  CHECK(m == "/tmp/rollspec_sections.ini:6: [ball] end = 0.5: lies beyond the span [0, length]");
}

TEST_CASE("modal beam section: parse keeps the values, modal_beam() refuses as study_modal_beam did") {
  const auto s = ball_on_beam("[beam]\nlength = 0.4\neffective_length = 0.3\n");
  const auto beam = study::ModalBeamSection::parse(s);  // no refusal at parse: the memory estimate reads it too
  CHECK(beam.properties.effective_length == 0.3);
  const std::string m = message_of([&] { (void)beam.modal_beam(); });
  CHECK(m.find("[beam] effective_length = 0.3: is shorter than [beam] length") != std::string::npos);
  const auto ok = study::ModalBeamSection::parse(ball_on_beam("[beam]\nmodes = 4\n")).modal_beam();
  CHECK(ok.modes() == 4);
}

TEST_CASE("stiffness section: one parse of the solver options, canonical texts for table inputs") {
  const auto s =
      ball_on_beam("[stiffness]\nhardness = 0\ntolerance = 1e-9\nmax_iterations = 500\nshape = paraboloid\n");
  const auto t = study::StiffnessSection::parse(s);
  CHECK(t.solver.hardness == std::numeric_limits<double>::infinity());
  CHECK(t.solver.tolerance == 1e-9);
  CHECK(t.solver.max_iterations == 500);
  CHECK(t.shape == contact::BallShape::Paraboloid);
  CHECK(t.value_text(t.solver.tolerance) == s.text("stiffness.tolerance"));
  CHECK(t.value_text(t.shape) == "paraboloid");
  CHECK(t.value_text(t.solver.hardness) == "0");  // the text as written: the table's hash input
  CHECK(t.rough);
  // A leave-one-out sub-table: its values and their texts, as the three --set texts would give.
  const auto sub = t.leaving_out(3);
  CHECK((sub.table_leave_out == 3 && sub.table == "auto" && sub.table_error == study::TableError::none));
  CHECK((sub.value_text(sub.table_leave_out) == "3" && sub.value_text(sub.table) == "auto" &&
         sub.value_text(sub.table_error) == "none"));
  CHECK(t.value_text(t.table_leave_out) == "-1");
  CHECK(study::StiffnessSection::leave_out_sets(3) ==
        std::vector<std::string>{"stiffness.table_leave_out=3", "stiffness.table=auto", "stiffness.table_error=none"});
  const auto leave = study::StiffnessSection::parse(ball_on_beam("", {"stiffness.table_leave_out=2"}));
  CHECK_FALSE(leave.table_error_auto);
  CHECK(leave.origin(leave.table_leave_out).where == "command line (--set): [stiffness] table_leave_out = 2");
  const auto hard = study::StiffnessSection::parse(ball_on_beam("[stiffness]\nhardness = 2e9\n"));
  CHECK(hard.solver.hardness == 2e9);
}

TEST_CASE("blocked-force grid from sections: a set window below 8 cells is refused at [blocked_force] window") {
  const auto s = ball_on_beam("[contact]\nlaw = linearised\nblocked_force = solver\n[blocked_force]\nwindow = 6\n");
  const auto ball = study::BallSection::parse(s);
  const auto beam = study::ModalBeamSection::parse(s);
  const double e_star = ball.effective_modulus(beam.properties.youngs_modulus, beam.poisson);
  const std::string m = message_of([&] {
    (void)stiffness::blocked_force_geometry(study::BlockedForceSection::parse(s), study::StripSurfaceSection::parse(s),
                                            texture_io::study_psd(s), ball.radius, e_star, ball.weight(), 0.0);
  });
  CHECK(m.find("[blocked_force] window = 6: leaves a solver window of 6 cells; allowed: 8 or more") !=
        std::string::npos);
  // Derived where not set: the same grid the plan prints.
  const auto d = ball_on_beam("[contact]\nlaw = linearised\nblocked_force = solver\n");
  const auto g =
      stiffness::blocked_force_geometry(study::BlockedForceSection::parse(d), study::StripSurfaceSection::parse(d),
                                        texture_io::study_psd(d), ball.radius, e_star, ball.weight(), 0.0);
  CHECK(g.window >= 8);
  CHECK(g.derived_cell);
  CHECK(study::PathTableSection::parse(d).approaches == 8);
}
