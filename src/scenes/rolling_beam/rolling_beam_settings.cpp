#include "src/scenes/rolling_beam/rolling_beam_settings.hpp"

#include <cmath>
#include <limits>

#include "src/scenes/rolling_beam/rolling_beam.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/rolling_analysis_section.hpp"
#include "src/study/sections/rolling_body_sections.hpp"
#include "src/study/sections/rolling_world_sections.hpp"

namespace rollspec::scenes {

using namespace study;
using Eigen::Vector3d;

namespace {

// Seed 000 examples 4.3 and 4.4 from the kernel's builders, with the study's contact law.
void build_example(const KeyReader& s, BodyKind kind, const Vector3d& g, const rolling::ContactLaw& law,
                   RollingBeamSettings& r) {
  if (kind == BodyKind::puck) {
    const auto disc = DiscSection::parse(s);
    const auto puck = PuckSection::parse(s);
    rolling::PuckParams p;
    p.radius = disc.radius;
    p.mass = disc.mass;
    p.height = disc.length;
    p.half_width = puck.half_width;
    p.mu = law.mu, p.eps_n = law.eps_n, p.eps_t = law.eps_t;
    p.v0 = disc.velocity;
    p.omega0 = disc.angular_velocity(1);
    p.force_peak = puck.force_peak;
    p.moment_peak = puck.moment_peak;
    p.pulse = puck.pulse;
    r.model = rolling::puck_model(p);
  } else {
    const auto fb = FlyingBeamSection::parse(s);
    r.flying.mu = law.mu, r.flying.eps_n = law.eps_n, r.flying.eps_t = law.eps_t;
    r.flying.force_peak = fb.force_peak;
    r.flying.ramp = fb.ramp;
    r.flying.force_end = r.flying.ramp + 1e-3;
    r.flying.wall_distance = fb.wall_distance;
    r.flying.g = g.norm();
    r.model = rolling::flying_beam_model(r.flying);
  }
}

// The rigid disc: one node, at rest on the first plane (static penetration m g / eps_n) or where
// [disc] puts it; returns that node.
int add_disc(const DiscSection& d, const Vector3d& g, rolling::Model& model, rolling::ContactLaw& law) {
  const double r = d.radius, m = d.mass, len = d.length;
  Vector3d x0;
  if (d.at_rest) {
    const auto& pl = model.planes[0];
    const double pen = m * std::abs(g.dot(pl.normal)) / law.eps_n;
    x0 = pl.point + (r - pen) * pl.normal;
  } else {
    x0 = d.position;
  }
  const int node = model.add_node(x0);
  model.v0 = {d.velocity};
  model.w0 = {d.angular_velocity};
  const double ia = 0.5 * m * r * r, it = m * (3.0 * r * r + len * len) / 12.0;
  model.bodies.push_back(rolling::RigidBody{node, m, Vector3d(it, it, ia).asDiagonal()});
  law.radius = r;
  return node;
}

int node_index(const KeyOrigin& at, double v, const std::vector<int>& ids) {
  if (v < 0 || v != std::floor(v) || v >= static_cast<double>(ids.size()))
    at.refuse("node " + std::to_string(v) + " does not exist; allowed: 0.." + std::to_string(ids.size() - 1));
  return ids[static_cast<std::size_t>(v)];
}

std::vector<int> node_list(const NodeList& list, const std::vector<int>& ids) {
  if (list.all) return ids;
  std::vector<int> out;
  for (double v : list.indices) out.push_back(node_index(list.origin, v, ids));
  return out;
}

}  // namespace

std::vector<KeySpec> rolling_beam_keys() {
  return joined_keys({BodySection::keys(), PuckSection::keys(), FlyingBeamSection::keys(), StraightBeamSection::keys(),
                      DiscSection::keys(), PlaneSection::keys(), RollingContactSection::keys(),
                      GravityVectorSection::keys(), SupportSection::keys(), ImposedSection::keys(),
                      RollingAnalysisSection::keys(), NodeOutputSection::keys()});
}

RollingBeamSettings read_rolling_beam_settings(const KeyReader& s) {
  RollingBeamSettings out;
  using namespace rolling;
  const BodyKind kind = BodySection::parse(s).kind;
  const bool disc = kind == BodyKind::disc;
  const auto gravity = GravityVectorSection::parse(s);
  const Vector3d g = gravity.acceleration;
  out.model.gravity = g;
  if (gravity.ramp_time > 0) out.model.gravity_series = TimeSeries::ramp(0.0, gravity.ramp_time);
  const auto planes = PlaneSection::parse(s);
  for (std::size_t i = 0; i < planes.points.size(); ++i)
    out.model.planes.push_back(make_plane(planes.points[i], planes.normals[i]));
  const auto contact = RollingContactSection::parse(s);
  ContactLaw law{0.0, contact.friction, contact.penalty_normal, contact.penalty_tangential, contact.rolling};
  std::vector<int> ids;
  double beam_length = 0.0;
  switch (kind) {
    case BodyKind::puck:
    case BodyKind::flying_beam:
      build_example(s, kind, g, law, out);
      ids.resize(out.model.X.size());
      for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
      break;
    case BodyKind::disc:
      ids.push_back(add_disc(DiscSection::parse(s), g, out.model, law));
      break;
    case BodyKind::beam: {
      const auto b = StraightBeamSection::parse(s);
      out.model.sections.push_back(
          circular_section(b.youngs_modulus, b.poisson, b.density, b.diameter, b.inner_diameter));
      ids = add_straight_beam(out.model, b.start, b.end, static_cast<int>(b.elements), 0, b.up);
      out.elements = b.elements;
      law.radius = 0.5 * b.diameter;
      beam_length = (b.end - b.start).norm();
      break;
    }
  }
  // Contacts (the example builders made theirs).
  if (out.model.contacts.empty()) {
    // Every contact node meets every plane (floor and walls); each pair keeps its own history.
    for (int n : node_list(contact.nodes, ids))
      for (int p = 0; p < static_cast<int>(out.model.planes.size()); ++p)
        out.model.contacts.push_back(ContactPair{n, p, law});
  }
  // Supports and imposed series.
  const auto support = SupportSection::parse(s);
  const ClampedEnds clamp = support.clamp;
  if (disc && clamp != ClampedEnds::none) support.origin(support.clamp).refuse("a disc has no ends to clamp");
  if (clamp == ClampedEnds::first || clamp == ClampedEnds::both)
    for (int d = 0; d < 6; ++d) out.model.imposed.push_back(ImposedDof{ids.front(), d, 0.0, TimeSeries::constant()});
  if (clamp == ClampedEnds::last || clamp == ClampedEnds::both)
    for (int d = 0; d < 6; ++d) out.model.imposed.push_back(ImposedDof{ids.back(), d, 0.0, TimeSeries::constant()});
  const auto imposed = ImposedSection::parse(s);
  if (imposed.node != ImposedNode::none) {
    const int node = imposed.node == ImposedNode::first ? ids.front() : ids.back();
    out.model.imposed.push_back(ImposedDof{node, imposed.dof, 1.0, TimeSeries{imposed.times, imposed.values}});
  }
  out.record = node_list(NodeOutputSection::parse(s).nodes, ids);
  const auto analysis = RollingAnalysisSection::parse(s);
  out.solver.analysis = analysis.dynamic ? Analysis::Dynamic : Analysis::QuasiStatic;
  out.solver.integrator = analysis.energy_consistent ? Integrator::EnergyConsistent : Integrator::Newmark;
  if (out.solver.integrator == Integrator::EnergyConsistent && !out.model.beams.empty())
    analysis.origin(analysis.integrator)
        .refuse("energy-consistent integration covers rigid bodies only; this model has beam elements");
  out.solver.impact_step_fraction = analysis.impact_step_fraction;
  out.solver.max_new_penetration = analysis.max_new_penetration;
  out.solver.max_iterations = static_cast<int>(analysis.max_iterations);
  out.solver.max_cuts = static_cast<int>(analysis.max_cuts);
  out.solver.max_line_search = static_cast<int>(analysis.line_search);
  out.solver.disp_tol = 1e-10;
  double mass = 0.0;
  for (const auto& b : out.model.bodies) mass += b.mass;
  if (kind == BodyKind::beam) mass = out.model.sections[0].rhoA * beam_length;
  if (kind == BodyKind::flying_beam) mass = out.flying.mass_per_length * out.flying.length;
  const double weight = mass * g.norm();
  out.solver.force_tol = analysis.tolerance * (weight > 0.0 ? weight : 1.0);
  out.run.dt = analysis.dt;
  out.run.t_end = analysis.t_end;
  out.run.record_every = static_cast<int>(analysis.record_every);
  out.run.record_nodes = out.record;
  out.step_where = analysis.origin(analysis.dt).where;
  return out;
}

std::vector<FirstKey> rolling_beam_first_keys() {
  return {first_key(&BodySection::kind),
          first_key(&StraightBeamSection::start),
          first_key(&StraightBeamSection::end),
          first_key(&StraightBeamSection::diameter),
          first_key(&StraightBeamSection::youngs_modulus),
          first_key(&StraightBeamSection::density),
          first_key(&RollingContactSection::friction),
          first_key(&GravityVectorSection::acceleration),
          first_key(&RollingAnalysisSection::dt),
          first_key(&RollingAnalysisSection::t_end)};
}

}  // namespace rollspec::scenes
