#pragma once
// What surrounds the body of scene rolling-beam, read once: the rigid [plane]s, the [contact] law
// and contact nodes, the [gravity] vector, the clamped ends ([support]) and an [imposed]
// displacement series. Checks that need the model (node indices, a disc's ends) are the scene's,
// at the kept origins.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

// One normal per point, none the zero vector.
struct PlaneSection : DeclaredSection<PlaneSection> {
  std::vector<Eigen::Vector3d> points, normals;

  static SectionKeys<PlaneSection> declare();
  void finish();  // checks across its keys, once they are read
};

// A list of node indices or "all" (contact and output nodes), checked against the model later.
struct NodeList {
  bool all = true;
  std::vector<double> indices;  // as written, when not all
  KeyOrigin origin;
};
// A NodeList text key ("all" or indices) with where it was set.
NodeList node_list(const KeyReader& s, const std::string& key);

// [contact] of rolling-beam (not ball-on-beam's nor rolling-pipe's).
struct RollingContactSection : DeclaredSection<RollingContactSection> {
  double friction = 0.0, penalty_normal = 0.0, penalty_tangential = 0.0;
  bool rolling = true;
  NodeList nodes;

  static SectionKeys<RollingContactSection> declare();
};

struct GravityVectorSection : DeclaredSection<GravityVectorSection> {
  Eigen::Vector3d acceleration;
  double ramp_time = 0.0;  // s; 0: constant

  static SectionKeys<GravityVectorSection> declare();
};

enum class ClampedEnds { none, first, last, both };
enum class ImposedNode { none, first, last };

inline constexpr ChoiceTable<ClampedEnds, 4> kClampedEnds{{
    {ClampedEnds::none, "none", ""},
    {ClampedEnds::first, "first", ""},
    {ClampedEnds::last, "last", ""},
    {ClampedEnds::both, "both", ""},
}};
inline constexpr ChoiceTable<ImposedNode, 3> kImposedNodes{{
    {ImposedNode::none, "none", ""},
    {ImposedNode::first, "first", ""},
    {ImposedNode::last, "last", ""},
}};
// The displacement component, as its index x, y, z = 0, 1, 2.
inline constexpr ChoiceTable<int, 3> kImposedDofs{{{0, "x", ""}, {1, "y", ""}, {2, "z", ""}}};

struct SupportSection : DeclaredSection<SupportSection> {
  ClampedEnds clamp = ClampedEnds::none;

  static SectionKeys<SupportSection> declare();
};

// times and values are read (and checked) only when a node is imposed.
struct ImposedSection : DeclaredSection<ImposedSection> {
  ImposedNode node = ImposedNode::none;
  int dof = 1;  // x, y, z as 0, 1, 2
  std::vector<double> times, values;

  static SectionKeys<ImposedSection> declare();
  void finish();  // checks across its keys, once they are read
};

}  // namespace rollspec::study
