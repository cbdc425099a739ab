#include "src/study/sections/rolling_world_sections.hpp"

#include <limits>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"
#include "src/study/sections/vector_keys.hpp"

namespace rollspec::study {

namespace {
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<KeySpec> PlaneSection::keys() {
  return {
      text_key("plane", "point", "a point of each rigid plane, x,y,z (m); several planes separated by ';'",
               std::string("0,0,0")),
      text_key("plane", "normal", "normal of each plane toward the body, x,y,z; ';' between planes",
               std::string("0,0,1")),
  };
}

PlaneSection PlaneSection::parse(const KeyReader& s) {
  PlaneSection p;
  p.points = triples(s, "plane.point");
  p.normals = triples(s, "plane.normal");
  if (p.points.size() != p.normals.size())
    s.refuse("plane.normal", "gives " + std::to_string(p.normals.size()) + " normals for " +
                                 std::to_string(p.points.size()) + " points; allowed: one normal per plane");
  for (std::size_t i = 0; i < p.points.size(); ++i)
    if (p.normals[i].norm() == 0.0)
      s.refuse("plane.normal", "plane " + std::to_string(i) + " has the zero vector as normal");
  return p;
}

std::vector<KeySpec> RollingContactSection::keys() {
  return {
      real_key("contact", "friction", "-", "Coulomb coefficient mu", std::string("0.5"), 0.0, inf),
      real_key("contact", "penalty_normal", "N/m", "normal penalty eps_n", std::string("1e9"), 0.0, inf, false),
      real_key("contact", "penalty_tangential", "N/m", "tangential penalty eps_t", std::string("1e7"), 0.0, inf, false),
      bool_key("contact", "rolling", "rolling correction of the tangential gap (false: the paper's 'no rolling')",
               std::string("true")),
      text_key("contact", "nodes", "contact nodes: all, or comma-separated node indices", std::string("all")),
  };
}

RollingContactSection RollingContactSection::parse(const KeyReader& s) {
  RollingContactSection c;
  c.friction = s.real("contact.friction");
  c.penalty_normal = s.real("contact.penalty_normal");
  c.penalty_tangential = s.real("contact.penalty_tangential");
  c.rolling = s.boolean("contact.rolling");
  c.nodes.all = s.text("contact.nodes") == "all";
  if (!c.nodes.all) c.nodes.indices = s.numbers("contact.nodes");
  c.nodes.origin = {s.where("contact.nodes")};
  return c;
}

std::vector<KeySpec> GravityVectorSection::keys() {
  return {
      text_key("gravity", "acceleration", "gravity x,y,z (m/s^2)", std::string("0,0,-9.81")),
      real_key("gravity", "ramp_time", "s", "gravity ramped in linearly over [0, ramp_time] (0: constant)",
               std::string("0"), 0.0, inf),
  };
}

GravityVectorSection GravityVectorSection::parse(const KeyReader& s) {
  return {vector3(s, "gravity.acceleration"), s.real("gravity.ramp_time")};
}

std::vector<KeySpec> SupportSection::keys() {
  return {
      choice_key("support", "clamp", "clamped end nodes of the beam", ClampedEnds::none, kClampedEnds),
  };
}

SupportSection SupportSection::parse(const KeyReader& s) {
  return {read_choice(s, "support.clamp", kClampedEnds), {s.where("support.clamp")}};
}

std::vector<KeySpec> ImposedSection::keys() {
  return {
      choice_key("imposed", "node", "node with an imposed displacement series", ImposedNode::none, kImposedNodes),
      choice_key("imposed", "dof", "imposed displacement component", 1, kImposedDofs),
      text_key("imposed", "times", "times of the piecewise-linear series (s), comma-separated", std::string("0")),
      text_key("imposed", "values", "displacements at those times (m)", std::string("0")),
  };
}

ImposedSection ImposedSection::parse(const KeyReader& s) {
  ImposedSection m;
  m.node = read_choice(s, "imposed.node", kImposedNodes);
  m.dof = read_choice(s, "imposed.dof", kImposedDofs);
  if (m.node == ImposedNode::none) return m;
  m.times = s.numbers("imposed.times");
  m.values = s.numbers("imposed.values");
  if (m.times.size() != m.values.size()) s.refuse("imposed.values", "needs one value per entry of [imposed] times");
  for (std::size_t i = 1; i < m.times.size(); ++i)
    if (!(m.times[i] > m.times[i - 1])) s.refuse("imposed.times", "must increase strictly");
  return m;
}

}  // namespace rollspec::study
