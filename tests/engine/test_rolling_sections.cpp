// Typed study sections of the rolling scenes (rolling-beam, rolling-pipe, random-oscillator): the
// values the study gives, the documented defaults, and cross-key refusals naming file:line.
#include <doctest/doctest.h>

#include <functional>
#include <string>

#include "src/error.hpp"
#include "src/scenes/random_oscillator/random_oscillator_settings.hpp"
#include "src/scenes/rolling_beam/rolling_beam_settings.hpp"
#include "src/scenes/rolling_pipe/rolling_pipe_settings.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/sections/random_oscillator_sections.hpp"
#include "src/study/sections/rolling_analysis_section.hpp"
#include "src/study/sections/rolling_body_sections.hpp"
#include "src/study/sections/rolling_pipe_sections.hpp"
#include "src/study/sections/rolling_world_sections.hpp"
#include "src/study/sections/study_section.hpp"
#include "tests/engine/study_from_text.hpp"

using namespace rollspec;
using test::message_of;

namespace {
const char* kFile = "/tmp/rollspec_rolling_sections.ini";

// Line 5 is the first line of `extra`.
study::Study scene_study(const std::string& scene, const std::string& extra) {
  return test::SceneStudies{kFile, scene, 2, 7}(extra);
}

// What `read` refuses the study of `scene` with `extra` with, as the user reads it ("" when it accepts it).
std::string refusal(const std::string& scene, const std::string& extra,
                    const std::function<void(const study::Study&)>& read) {
  const auto s = scene_study(scene, extra);
  return message_of([&] { read(s); });
}

}  // namespace

TEST_CASE("rolling-beam sections: values from the study, defaults elsewhere") {
  const auto s =
      scene_study("rolling-beam",
                  "[body]\nkind = disc\n[disc]\nradius = 0.25\nvelocity = 1, 0, 0\n"
                  "[plane]\npoint = 0,0,0; 5,0,0\nnormal = 0,0,1; -1,0,0\n[gravity]\nacceleration = 0,0,-9\n");
  CHECK(study::BodySection::parse(s).kind == study::BodyKind::disc);
  const auto disc = study::DiscSection::parse(s);
  CHECK(disc.radius == 0.25);
  CHECK(disc.mass == 1000.0);  // default
  CHECK(disc.at_rest);
  CHECK(disc.velocity == Eigen::Vector3d(1, 0, 0));
  const auto planes = study::PlaneSection::parse(s);
  REQUIRE(planes.points.size() == 2);
  CHECK(planes.normals[1] == Eigen::Vector3d(-1, 0, 0));
  CHECK(study::GravityVectorSection::parse(s).acceleration == Eigen::Vector3d(0, 0, -9));
  const auto a = study::RollingAnalysisSection::parse(s);
  CHECK(a.dt == 1e-3);  // defaults
  CHECK(a.max_iterations == 30);
  CHECK(a.dynamic);
  CHECK_FALSE(a.energy_consistent);
  const auto c = study::RollingContactSection::parse(s);
  CHECK(c.friction == 0.5);
  CHECK(c.nodes.all);
  CHECK(study::ImposedSection::parse(s).node == study::ImposedNode::none);
  CHECK(study::StraightBeamSection::parse(s).elements == 20);
}

TEST_CASE("rolling-beam sections: cross-key refusals name file:line") {
  CHECK(refusal("rolling-beam", "[plane]\npoint = 0,0,0; 1,0,0\nnormal = 0,0,1\n", study::PlaneSection::parse) ==
        std::string(kFile) + ":7: [plane] normal = 0,0,1: gives 1 normals for 2 points; allowed: one normal per plane");
  CHECK(refusal("rolling-beam", "[beam]\ndiameter = 0.2\ninner_diameter = 0.2\n", study::StraightBeamSection::parse) ==
        std::string(kFile) + ":7: [beam] inner_diameter = 0.2: must be smaller than [beam] diameter");
  CHECK(refusal("rolling-beam", "[imposed]\nnode = last\ntimes = 0, 1, 1\nvalues = 0, 1, 2\n",
                study::ImposedSection::parse) ==
        std::string(kFile) + ":7: [imposed] times = 0, 1, 1: must increase strictly");
  // Checks made once the model is known keep the key's origin.
  CHECK(refusal("rolling-beam", "[beam]\nelements = 2\n[output]\nnodes = 0, 9\n", scenes::read_rolling_beam_settings) ==
        std::string(kFile) + ":8: [output] nodes = 0, 9: node 9.000000 does not exist; allowed: 0..4");
  CHECK(
      refusal("rolling-beam", "[body]\nkind = disc\n[support]\nclamp = first\n", scenes::read_rolling_beam_settings) ==
      std::string(kFile) + ":8: [support] clamp = first: a disc has no ends to clamp");
  CHECK(refusal("rolling-beam", "[analysis]\nintegrator = energy-consistent\n", scenes::read_rolling_beam_settings) ==
        std::string(kFile) +
            ":6: [analysis] integrator = energy-consistent: energy-consistent integration covers rigid bodies only; "
            "this model has beam elements");
  CHECK(refusal("rolling-beam", "[analysis]\ndt = 0.5\nt_end = 0.1\n", study::RollingAnalysisSection::parse) ==
        std::string(kFile) + ":6: [analysis] dt = 0.5: exceeds [analysis] t_end");
}

TEST_CASE("rolling-pipe sections: values, defaults and refusals at file:line") {
  const auto s = scene_study("rolling-pipe", "[pipe]\nlength = 0.8\n[sensors]\npositions = 0.25, 0.75\n");
  const auto pipe = study::PipeSection::parse(s);
  CHECK(pipe.length == 0.8);
  CHECK(pipe.diameter == 0.06);  // default
  CHECK(pipe.elements == 4);
  CHECK(study::PipeSensorsSection::parse(s).positions == std::vector<double>{0.25, 0.75});
  CHECK(study::PipeRoughnessSection::parse(s).line);
  CHECK(study::PipeContactSection::parse(s).damping_ratio == 0.1);
  CHECK(study::PipeAnalysisSection::parse(s).dt == 1e-4);
  CHECK(study::StudySection::parse(s).seed == 7);
  CHECK(refusal("rolling-pipe", "[pipe]\ndiameter = 0.05\ninner_diameter = 0.05\n", study::PipeSection::parse) ==
        std::string(kFile) + ":7: [pipe] inner_diameter = 0.05: must be smaller than [pipe] diameter");
  CHECK(refusal("rolling-pipe", "[analysis]\ndt = 2e-5\n[sensors]\npositions = 0.5, 1.5\n",
                scenes::read_rolling_pipe_settings) ==
        std::string(kFile) + ":8: [sensors] positions = 0.5, 1.5: fraction 1.500000 lies outside [0, 1]");
  CHECK(refusal("rolling-pipe", "[roll]\ndistance = 1e-4\n", scenes::read_rolling_pipe_settings) ==
        std::string(kFile) + ":6: [roll] distance = 1e-04: gives fewer than 16 time steps at [analysis] dt");
}

TEST_CASE("random-oscillator sections: values, defaults and refusals at file:line") {
  const auto s =
      scene_study("random-oscillator", "[oscillator]\nnatural_frequency = 50\n[force]\namplitudes = deterministic\n");
  const auto o = study::OscillatorSection::parse(s);
  CHECK(o.natural_frequency == 50.0);
  CHECK(o.damping_ratio == 0.02);  // default
  const auto f = study::ForceSection::parse(s);
  CHECK(f.amplitudes == spectral::Amplitudes::deterministic);
  CHECK(f.f_max == 0.0);
  const auto sig = study::RecordSignalSection::parse(s);
  CHECK(sig.samples == 2048u * 32u);
  CHECK(refusal("random-oscillator", "[oscillator]\nnatural_frequency = 2000\n",
                scenes::read_random_oscillator_settings) ==
        std::string(kFile) +
            ":6: [oscillator] natural_frequency = 2000: must lie below the Nyquist frequency f_s/2 = 1024.000000 Hz");
  CHECK(refusal("random-oscillator", "[oscillator]\nnatural_frequency = 50\n[force]\nf_max = 2000\n",
                scenes::read_random_oscillator_settings) ==
        std::string(kFile) + ":8: [force] f_max = 2000: exceeds the Nyquist frequency f_s/2 = 1024.000000 Hz");
  CHECK(refusal("random-oscillator", "[oscillator]\nnatural_frequency = 50\n[signal]\nduration = 1e-3\n",
                study::RecordSignalSection::parse)
            .find(std::string(kFile) + ":8: [signal] duration = 0.001: gives") == 0);
}
