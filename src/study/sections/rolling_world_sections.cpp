#include "src/study/sections/rolling_world_sections.hpp"

#include "src/study/sections/section_keys.hpp"
#include "src/study/sections/vector_keys.hpp"

namespace rollspec::study {

NodeList node_list(const KeyReader& s, const std::string& key) {
  NodeList n;
  n.all = s.text(key) == "all";
  if (!n.all) n.indices = s.numbers(key);
  n.origin = {s.where(key)};
  return n;
}

SectionKeys<PlaneSection> PlaneSection::declare() {
  using T = PlaneSection;
  return SectionKeys<T>("plane")
      .text("point", &T::points, "a point of each rigid plane, x,y,z (m); several planes separated by ';'", "0,0,0",
            triples)
      .text("normal", &T::normals, "normal of each plane toward the body, x,y,z; ';' between planes", "0,0,1", triples);
}
template struct DeclaredSection<PlaneSection>;

SectionKeys<RollingContactSection> RollingContactSection::declare() {
  using T = RollingContactSection;
  return SectionKeys<T>("contact")
      .real("friction", &T::friction, "-", "Coulomb coefficient mu", "0.5", at_least(0.0))
      .real("penalty_normal", &T::penalty_normal, "N/m", "normal penalty eps_n", "1e9", above(0.0))
      .real("penalty_tangential", &T::penalty_tangential, "N/m", "tangential penalty eps_t", "1e7", above(0.0))
      .boolean("rolling", &T::rolling, "rolling correction of the tangential gap (false: the paper's 'no rolling')",
               "true")
      .text("nodes", &T::nodes, "contact nodes: all, or comma-separated node indices", "all", node_list);
}
template struct DeclaredSection<RollingContactSection>;

SectionKeys<GravityVectorSection> GravityVectorSection::declare() {
  using T = GravityVectorSection;
  return SectionKeys<T>("gravity")
      .text("acceleration", &T::acceleration, "gravity x,y,z (m/s^2)", "0,0,-9.81", vector3)
      .real("ramp_time", &T::ramp_time, "s", "gravity ramped in linearly over [0, ramp_time] (0: constant)", "0",
            at_least(0.0));
}
template struct DeclaredSection<GravityVectorSection>;

SectionKeys<SupportSection> SupportSection::declare() {
  using T = SupportSection;
  return SectionKeys<T>("support").choice("clamp", &T::clamp, "clamped end nodes of the beam", ClampedEnds::none,
                                          kClampedEnds);
}
template struct DeclaredSection<SupportSection>;

SectionKeys<ImposedSection> ImposedSection::declare() {
  using T = ImposedSection;
  const auto imposed = [](const T& m) { return m.node != ImposedNode::none; };
  return SectionKeys<T>("imposed")
      .choice("node", &T::node, "node with an imposed displacement series", ImposedNode::none, kImposedNodes)
      .choice("dof", &T::dof, "imposed displacement component", 1, kImposedDofs)
      .text("times", &T::times, "times of the piecewise-linear series (s), comma-separated", "0", number_list)
      .when(imposed)
      .text("values", &T::values, "displacements at those times (m)", "0", number_list)
      .when(imposed);
}
template struct DeclaredSection<ImposedSection>;

void PlaneSection::finish() {
  if (points.size() != normals.size())
    origin(normals).refuse("gives " + std::to_string(normals.size()) + " normals for " + std::to_string(points.size()) +
                           " points; allowed: one normal per plane");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (normals[i].norm() == 0.0)
      origin(normals).refuse("plane " + std::to_string(i) + " has the zero vector as normal");
}

void ImposedSection::finish() {
  if (node == ImposedNode::none) return;
  if (times.size() != values.size()) origin(values).refuse("needs one value per entry of [imposed] times");
  for (std::size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1])) origin(times).refuse("must increase strictly");
}

}  // namespace rollspec::study
