#pragma once
// The sections of scene rolling-pipe, read once: the tube ([pipe]), the roll ([roll]), the line or
// isotropic [roughness], the node [contact] law, [gravity], the step ([analysis]) and the
// [sensors] as fractions of the tube's length. Checks that span sections (the step against the
// contact oscillation, the rolled strip) are the scene's, at the kept origins.
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

// inner_diameter < diameter is checked here.
struct PipeSection : DeclaredSection<PipeSection> {
  double length = 0.0, diameter = 0.0, inner_diameter = 0.0, youngs_modulus = 0.0, poisson = 0.0, density = 0.0;
  long long elements = 0;

  static SectionKeys<PipeSection> declare();
  void finish();  // checks across its keys, once they are read
};

struct RollSection : DeclaredSection<RollSection> {
  double speed = 0.0, distance = 0.0;

  static SectionKeys<RollSection> declare();
};

enum class PipeRoughnessKind { line, isotropic };

inline constexpr ChoiceTable<PipeRoughnessKind, 2> kPipeRoughnessKinds{{
    {PipeRoughnessKind::line, "line", "a line texture along the rolling direction, the same under every node"},
    {PipeRoughnessKind::isotropic, "isotropic",
     "an isotropic surface realisation from [surface] (spectral or seed method), different under every node"},
}};

struct PipeRoughnessSection : DeclaredSection<PipeRoughnessSection> {
  PipeRoughnessKind kind = PipeRoughnessKind::line;
  bool line = true;      // kind = line (else an isotropic surface from [surface])
  double spacing = 0.0;  // m, of the line texture

  static SectionKeys<PipeRoughnessSection> declare();
  void finish();  // line from kind
};

struct PipeContactSection : DeclaredSection<PipeContactSection> {
  double friction = 0.0, penalty_normal = 0.0, penalty_tangential = 0.0, damping_ratio = 0.0;
  bool rolling = true;

  static SectionKeys<PipeContactSection> declare();
};

struct PipeGravitySection : DeclaredSection<PipeGravitySection> {
  double acceleration = 0.0;  // m/s^2, normal to the mean surface

  static SectionKeys<PipeGravitySection> declare();
};

struct PipeAnalysisSection : DeclaredSection<PipeAnalysisSection> {
  double dt = 0.0, tolerance = 0.0;

  static SectionKeys<PipeAnalysisSection> declare();
};

// [sensors] of rolling-pipe: fractions of the tube's length (ball-on-beam's SensorsSection holds
// positions in metres), checked against [0, 1] by the scene at origin(positions).
struct PipeSensorsSection : DeclaredSection<PipeSensorsSection> {
  std::vector<double> positions;
  bool average = true;

  static SectionKeys<PipeSensorsSection> declare();
};

}  // namespace rollspec::study
