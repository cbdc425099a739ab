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

namespace {

const SectionKeys<PlaneSection>& plane_keys() {
  using T = PlaneSection;
  static const auto k =
      SectionKeys<T>("plane")
          .text("point", &T::points, "a point of each rigid plane, x,y,z (m); several planes separated by ';'", "0,0,0",
                triples)
          .text("normal", &T::normals, "normal of each plane toward the body, x,y,z; ';' between planes", "0,0,1",
                triples);
  return k;
}

const SectionKeys<RollingContactSection>& contact_keys() {
  using T = RollingContactSection;
  static const auto k =
      SectionKeys<T>("contact")
          .real("friction", &T::friction, "-", "Coulomb coefficient mu", "0.5", at_least(0.0))
          .real("penalty_normal", &T::penalty_normal, "N/m", "normal penalty eps_n", "1e9", above(0.0))
          .real("penalty_tangential", &T::penalty_tangential, "N/m", "tangential penalty eps_t", "1e7", above(0.0))
          .boolean("rolling", &T::rolling, "rolling correction of the tangential gap (false: the paper's 'no rolling')",
                   "true")
          .text("nodes", &T::nodes, "contact nodes: all, or comma-separated node indices", "all", node_list);
  return k;
}

const SectionKeys<GravityVectorSection>& gravity_keys() {
  using T = GravityVectorSection;
  static const auto k = SectionKeys<T>("gravity")
                            .text("acceleration", &T::acceleration, "gravity x,y,z (m/s^2)", "0,0,-9.81", vector3)
                            .real("ramp_time", &T::ramp_time, "s",
                                  "gravity ramped in linearly over [0, ramp_time] (0: constant)", "0", at_least(0.0));
  return k;
}

const SectionKeys<SupportSection>& support_keys() {
  using T = SupportSection;
  static const auto k = SectionKeys<T>("support").choice("clamp", &T::clamp, "clamped end nodes of the beam",
                                                         ClampedEnds::none, kClampedEnds);
  return k;
}

const SectionKeys<ImposedSection>& imposed_keys() {
  using T = ImposedSection;
  const auto imposed = [](const T& m) { return m.node != ImposedNode::none; };
  static const auto k =
      SectionKeys<T>("imposed")
          .choice("node", &T::node, "node with an imposed displacement series", ImposedNode::none, kImposedNodes)
          .choice("dof", &T::dof, "imposed displacement component", 1, kImposedDofs)
          .text("times", &T::times, "times of the piecewise-linear series (s), comma-separated", "0", number_list)
          .when(imposed)
          .text("values", &T::values, "displacements at those times (m)", "0", number_list)
          .when(imposed);
  return k;
}

}  // namespace

std::vector<KeySpec> PlaneSection::keys() { return plane_keys().keys(); }

PlaneSection PlaneSection::parse(const KeyReader& s) {
  const PlaneSection p = plane_keys().read(s);
  if (p.points.size() != p.normals.size())
    p.origin(p.normals).refuse("gives " + std::to_string(p.normals.size()) + " normals for " +
                               std::to_string(p.points.size()) + " points; allowed: one normal per plane");
  for (std::size_t i = 0; i < p.points.size(); ++i)
    if (p.normals[i].norm() == 0.0)
      p.origin(p.normals).refuse("plane " + std::to_string(i) + " has the zero vector as normal");
  return p;
}

std::vector<KeySpec> RollingContactSection::keys() { return contact_keys().keys(); }
RollingContactSection RollingContactSection::parse(const KeyReader& s) { return contact_keys().read(s); }

std::vector<KeySpec> GravityVectorSection::keys() { return gravity_keys().keys(); }
GravityVectorSection GravityVectorSection::parse(const KeyReader& s) { return gravity_keys().read(s); }

std::vector<KeySpec> SupportSection::keys() { return support_keys().keys(); }
SupportSection SupportSection::parse(const KeyReader& s) { return support_keys().read(s); }

std::vector<KeySpec> ImposedSection::keys() { return imposed_keys().keys(); }

ImposedSection ImposedSection::parse(const KeyReader& s) {
  const ImposedSection m = imposed_keys().read(s);
  if (m.node == ImposedNode::none) return m;
  if (m.times.size() != m.values.size()) m.origin(m.values).refuse("needs one value per entry of [imposed] times");
  for (std::size_t i = 1; i < m.times.size(); ++i)
    if (!(m.times[i] > m.times[i - 1])) m.origin(m.times).refuse("must increase strictly");
  return m;
}

}  // namespace rollspec::study
