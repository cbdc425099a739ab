#include "src/scenes/rolling_beam_settings.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "src/study/key_reader.hpp"

namespace rollspec::scenes {

using namespace study;
using Eigen::Vector3d;

namespace {
const double inf = std::numeric_limits<double>::infinity();

// ';'-separated x,y,z triples.
std::vector<Vector3d> triples(const KeyReader& s, const std::string& key) {
  std::vector<Vector3d> out;
  std::istringstream in(s.text(key));
  std::string item;
  while (std::getline(in, item, ';')) {
    std::vector<double> v;
    std::istringstream parts(item);
    std::string part;
    while (std::getline(parts, part, ',')) {
      char* end = nullptr;
      const double x = std::strtod(part.c_str(), &end);
      while (end && (*end == ' ' || *end == '\t')) ++end;
      if (end == part.c_str() || *end != '\0' || !std::isfinite(x))
        s.refuse(key, "'" + part + "' is not a finite number");
      v.push_back(x);
    }
    if (v.size() != 3) s.refuse(key, "'" + item + "' is not x,y,z; allowed: x,y,z triples separated by ';'");
    out.emplace_back(v[0], v[1], v[2]);
  }
  return out;
}

Vector3d vec(const KeyReader& s, const std::string& key) {
  const auto v = s.numbers(key, 3);
  return {v[0], v[1], v[2]};
}

// Seed 000 examples 4.3 and 4.4 from the kernel's builders, with the study's contact law.
void build_example(const KeyReader& s, const std::string& kind, const rolling::ContactLaw& law, RollingBeamSettings& r) {
  if (kind == "puck") {
    rolling::PuckParams p;
    p.radius = s.real("disc.radius");
    p.mass = s.real("disc.mass");
    p.height = s.real("disc.length");
    p.half_width = s.real("puck.half_width");
    p.mu = law.mu, p.eps_n = law.eps_n, p.eps_t = law.eps_t;
    p.v0 = vec(s, "disc.velocity");
    p.omega0 = vec(s, "disc.angular_velocity")(1);
    p.force_peak = s.real("puck.force_peak");
    p.moment_peak = s.real("puck.moment_peak");
    p.pulse = s.real("puck.pulse");
    r.model = rolling::puck_model(p);
  } else {
    r.flying.mu = law.mu, r.flying.eps_n = law.eps_n, r.flying.eps_t = law.eps_t;
    r.flying.force_peak = s.real("flying_beam.force_peak");
    r.flying.ramp = s.real("flying_beam.ramp");
    r.flying.force_end = r.flying.ramp + 1e-3;
    r.flying.wall_distance = s.real("flying_beam.wall_distance");
    r.flying.g = vec(s, "gravity.acceleration").norm();
    r.model = rolling::flying_beam_model(r.flying);
  }
}

int node_index(const KeyReader& s, const std::string& key, double v, const std::vector<int>& ids) {
  if (v < 0 || v != std::floor(v) || v >= static_cast<double>(ids.size()))
    s.refuse(key, "node " + std::to_string(v) + " does not exist; allowed: 0.." + std::to_string(ids.size() - 1));
  return ids[static_cast<std::size_t>(v)];
}

}  // namespace

std::vector<KeySpec> rolling_beam_keys() {
  return {
      choice_key(
          "body", "kind",
          "a geometrically exact beam, a rigid disc (one node), or the seed 000 builders: puck (4.3, four walls, "
          "[puck] keys) and flying-beam (4.4, floor and an oblique wall); the builders define their own planes",
          std::string("beam"), {"beam", "disc", "puck", "flying-beam"}),
      real_key("puck", "half_width", "m", "walls at x, z = +-half_width (seed 000 example 4.3)", std::string("1"), 0.0,
               inf, false),
      real_key("puck", "force_peak", "N", "peak of the triangular force pulse along z", std::string("3e4"), -inf, inf),
      real_key("puck", "moment_peak", "N m", "peak of the triangular moment pulse about y", std::string("1.5e4"), -inf,
               inf),
      real_key("puck", "pulse", "s", "duration of the triangular pulse", std::string("0.1"), 0.0, inf, false),
      real_key("flying_beam", "force_peak", "N", "lateral force at the centre node, ramped up over [0, ramp]",
               std::string("1e3"), -inf, inf),
      real_key("flying_beam", "ramp", "s", "ramp time of the lateral force", std::string("1"), 0.0, inf, false),
      real_key("flying_beam", "wall_distance", "m", "distance of the oblique wall", std::string("1000"), 0.0, inf,
               false),
      text_key("beam", "start", "first end of the straight beam, x,y,z (m)", std::string("0,0,0")),
      text_key("beam", "end", "second end, x,y,z (m)", std::string("10,0,0")),
      text_key("beam", "up", "direction of the section's e2 axis, x,y,z", std::string("0,1,0")),
      integer_key("beam", "elements", "quadratic 3-node elements", std::string("20"), 1, 100000),
      real_key("beam", "diameter", "m", "outer diameter (also the contact sphere's diameter)", std::string("0.3"), 0.0,
               inf, false),
      real_key("beam", "inner_diameter", "m", "inner diameter of a tube (0: solid)", std::string("0"), 0.0, inf),
      real_key("beam", "youngs_modulus", "Pa", "Young's modulus", std::string("1e7"), 0.0, inf, false),
      real_key("beam", "poisson", "-", "Poisson's ratio", std::string("0"), -1.0, 0.5, false, true),
      real_key("beam", "density", "kg/m^3", "density", std::string("1e5"), 0.0, inf, false),
      real_key("disc", "radius", "m", "disc radius (contact sphere radius)", std::string("0.2"), 0.0, inf, false),
      real_key("disc", "length", "m", "disc length along its axis (transverse inertia)", std::string("1"), 0.0, inf,
               false),
      real_key("disc", "mass", "kg", "disc mass", std::string("1000"), 0.0, inf, false),
      text_key("disc", "position", "centre x,y,z (m); 'rest' puts it on the plane at its static penetration",
               std::string("rest")),
      text_key("disc", "velocity", "initial velocity x,y,z (m/s)", std::string("0,0,0")),
      text_key("disc", "angular_velocity", "initial angular velocity x,y,z (rad/s); the disc's axis is z",
               std::string("0,0,0")),
      text_key("plane", "point", "a point of each rigid plane, x,y,z (m); several planes separated by ';'",
               std::string("0,0,0")),
      text_key("plane", "normal", "normal of each plane toward the body, x,y,z; ';' between planes",
               std::string("0,0,1")),
      real_key("contact", "friction", "-", "Coulomb coefficient mu", std::string("0.5"), 0.0, inf),
      real_key("contact", "penalty_normal", "N/m", "normal penalty eps_n", std::string("1e9"), 0.0, inf, false),
      real_key("contact", "penalty_tangential", "N/m", "tangential penalty eps_t", std::string("1e7"), 0.0, inf, false),
      bool_key("contact", "rolling", "rolling correction of the tangential gap (false: the paper's 'no rolling')",
               std::string("true")),
      text_key("contact", "nodes", "contact nodes: all, or comma-separated node indices", std::string("all")),
      text_key("gravity", "acceleration", "gravity x,y,z (m/s^2)", std::string("0,0,-9.81")),
      real_key("gravity", "ramp_time", "s", "gravity ramped in linearly over [0, ramp_time] (0: constant)",
               std::string("0"), 0.0, inf),
      choice_key("support", "clamp", "clamped end nodes of the beam", std::string("none"),
                 {"none", "first", "last", "both"}),
      choice_key("imposed", "node", "node with an imposed displacement series", std::string("none"),
                 {"none", "first", "last"}),
      choice_key("imposed", "dof", "imposed displacement component", std::string("y"), {"x", "y", "z"}),
      text_key("imposed", "times", "times of the piecewise-linear series (s), comma-separated", std::string("0")),
      text_key("imposed", "values", "displacements at those times (m)", std::string("0")),
      choice_key("analysis", "type", "dynamic (Newmark trapezoidal) or static (quasi-static load steps)",
                 std::string("dynamic"), {"dynamic", "static"}),
      real_key("analysis", "dt", "s", "time (load) step", std::string("1e-3"), 0.0, inf, false),
      real_key("analysis", "t_end", "s", "end time", std::string("1"), 0.0, inf, false),
      choice_key(
          "analysis", "integrator",
          "dynamic integrator: newmark (trapezoidal) or energy-consistent (midpoint + discrete-gradient penalty; "
          "rigid bodies only)",
          std::string("newmark"), {"newmark", "energy-consistent"}),
      real_key("analysis", "impact_step_fraction", "-",
               "while a contact is closed or closing, limit the step to this fraction of 2 pi sqrt(m/eps_n) (0: off)",
               std::string("0"), 0.0, 1.0),
      real_key("analysis", "max_new_penetration", "m", "cut steps in which a contact closes deeper than this (0: off)",
               std::string("0"), 0.0, inf),
      integer_key("analysis", "record_every", "steps between recorded states", std::string("1"), 1, 1e9),
      integer_key("analysis", "max_iterations", "Newton iterations per step before cutting it", std::string("30"), 1,
                  10000),
      integer_key("analysis", "max_cuts", "step halvings allowed", std::string("12"), 0, 60),
      integer_key("analysis", "line_search", "backtracking halvings per Newton iteration", std::string("12"), 0, 60),
      real_key("analysis", "tolerance", "-",
               "Newton convergence: residual 2-norm relative to the body's weight (1 N without gravity)",
               std::string("1e-6"), 0.0, 1.0, false),
      text_key("output", "nodes", "recorded nodes: all, or comma-separated indices", std::string("all")),
  };
}

RollingBeamSettings read_rolling_beam_settings(const KeyReader& s) {
  RollingBeamSettings out;
  using namespace rolling;
  const bool disc = s.text("body.kind") == "disc";
  const Vector3d g = vec(s, "gravity.acceleration");
  out.model.gravity = g;
  if (s.real("gravity.ramp_time") > 0) out.model.gravity_series = TimeSeries::ramp(0.0, s.real("gravity.ramp_time"));
  const auto points = triples(s, "plane.point"), normals = triples(s, "plane.normal");
  if (points.size() != normals.size())
    s.refuse("plane.normal", "gives " + std::to_string(normals.size()) + " normals for " +
                                 std::to_string(points.size()) + " points; allowed: one normal per plane");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (normals[i].norm() == 0.0)
      s.refuse("plane.normal", "plane " + std::to_string(i) + " has the zero vector as normal");
    out.model.planes.push_back(make_plane(points[i], normals[i]));
  }
  ContactLaw law{0.0, s.real("contact.friction"), s.real("contact.penalty_normal"),
                 s.real("contact.penalty_tangential"), s.boolean("contact.rolling")};
  std::vector<int> ids;
  const std::string kind = s.text("body.kind");
  if (kind == "puck" || kind == "flying-beam") {
    build_example(s, kind, law, out);
    ids.resize(out.model.X.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
  } else if (disc) {
    const double r = s.real("disc.radius"), m = s.real("disc.mass"), len = s.real("disc.length");
    Vector3d x0;
    if (s.text("disc.position") == "rest") {
      const auto& pl = out.model.planes[0];
      const double pen =
          m * std::abs(g.dot(pl.normal)) / law.eps_n;  // on the first plane  // static penetration m g / eps_n
      x0 = pl.point + (r - pen) * pl.normal;
    } else {
      x0 = vec(s, "disc.position");
    }
    ids.push_back(out.model.add_node(x0));
    out.model.v0 = {vec(s, "disc.velocity")};
    out.model.w0 = {vec(s, "disc.angular_velocity")};
    const double ia = 0.5 * m * r * r, it = m * (3.0 * r * r + len * len) / 12.0;
    out.model.bodies.push_back(RigidBody{ids[0], m, Vector3d(it, it, ia).asDiagonal()});
    law.radius = r;
  } else {
    const double d = s.real("beam.diameter"), di = s.real("beam.inner_diameter");
    if (di >= d) s.refuse("beam.inner_diameter", "must be smaller than [beam] diameter");
    out.model.sections.push_back(
        circular_section(s.real("beam.youngs_modulus"), s.real("beam.poisson"), s.real("beam.density"), d, di));
    const Vector3d a = vec(s, "beam.start"), b = vec(s, "beam.end");
    if ((b - a).norm() == 0.0) s.refuse("beam.end", "coincides with [beam] start");
    ids = add_straight_beam(out.model, a, b, static_cast<int>(s.integer("beam.elements")), 0, vec(s, "beam.up"));
    law.radius = 0.5 * d;
  }
  // Contacts (the example builders made theirs).
  std::vector<int> contact_nodes;

  if (out.model.contacts.empty()) {
    if (s.text("contact.nodes") == "all")
      contact_nodes = ids;
    else
      for (double v : s.numbers("contact.nodes")) contact_nodes.push_back(node_index(s, "contact.nodes", v, ids));
    // Every contact node meets every plane (floor and walls); each pair keeps its own history.
    for (int n : contact_nodes)
      for (int p = 0; p < static_cast<int>(out.model.planes.size()); ++p)
        out.model.contacts.push_back(ContactPair{n, p, law});
  }
  // Supports and imposed series.
  const std::string clamp = s.text("support.clamp");
  if (disc && clamp != "none") s.refuse("support.clamp", "a disc has no ends to clamp");
  if (clamp == "first" || clamp == "both")
    for (int d = 0; d < 6; ++d) out.model.imposed.push_back(ImposedDof{ids.front(), d, 0.0, TimeSeries::constant()});
  if (clamp == "last" || clamp == "both")
    for (int d = 0; d < 6; ++d) out.model.imposed.push_back(ImposedDof{ids.back(), d, 0.0, TimeSeries::constant()});
  if (s.text("imposed.node") != "none") {
    const auto t = s.numbers("imposed.times"), v = s.numbers("imposed.values");
    if (t.size() != v.size()) s.refuse("imposed.values", "needs one value per entry of [imposed] times");
    for (std::size_t i = 1; i < t.size(); ++i)
      if (!(t[i] > t[i - 1])) s.refuse("imposed.times", "must increase strictly");
    const int node = s.text("imposed.node") == "first" ? ids.front() : ids.back();
    const int dof = s.text("imposed.dof") == "x" ? 0 : s.text("imposed.dof") == "y" ? 1 : 2;
    out.model.imposed.push_back(ImposedDof{node, dof, 1.0, TimeSeries{t, v}});
  }
  if (s.text("output.nodes") == "all")
    out.record = ids;
  else
    for (double v : s.numbers("output.nodes")) out.record.push_back(node_index(s, "output.nodes", v, ids));
  out.solver.analysis = s.text("analysis.type") == "dynamic" ? Analysis::Dynamic : Analysis::QuasiStatic;
  out.solver.integrator =
      s.text("analysis.integrator") == "energy-consistent" ? Integrator::EnergyConsistent : Integrator::Newmark;
  if (out.solver.integrator == Integrator::EnergyConsistent && !out.model.beams.empty())
    s.refuse("analysis.integrator",
             "energy-consistent integration covers rigid bodies only; this model has beam elements");
  out.solver.impact_step_fraction = s.real("analysis.impact_step_fraction");
  out.solver.max_new_penetration = s.real("analysis.max_new_penetration");
  out.solver.max_iterations = static_cast<int>(s.integer("analysis.max_iterations"));
  out.solver.max_cuts = static_cast<int>(s.integer("analysis.max_cuts"));
  out.solver.max_line_search = static_cast<int>(s.integer("analysis.line_search"));
  out.solver.disp_tol = 1e-10;
  double mass = 0.0;
  for (const auto& b : out.model.bodies) mass += b.mass;
  if (kind == "beam") mass = out.model.sections[0].rhoA * (vec(s, "beam.end") - vec(s, "beam.start")).norm();
  if (kind == "flying-beam") mass = out.flying.mass_per_length * out.flying.length;
  const double weight = mass * g.norm();
  out.solver.force_tol = s.real("analysis.tolerance") * (weight > 0.0 ? weight : 1.0);
  out.run.dt = s.real("analysis.dt");
  out.run.t_end = s.real("analysis.t_end");
  if (out.run.dt > out.run.t_end) s.refuse("analysis.dt", "exceeds [analysis] t_end");
  if (out.run.t_end / out.run.dt > 1e8) s.refuse("analysis.dt", "gives more than 1e8 steps");
  out.run.record_every = static_cast<int>(s.integer("analysis.record_every"));
  out.run.record_nodes = out.record;
  out.step_where = s.where("analysis.dt");
  return out;
}

}  // namespace rollspec::scenes
