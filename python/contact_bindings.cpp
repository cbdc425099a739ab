// rollspec.contact: the elastic and elastic-plastic half-space solve of the stiffness tables
// (kernels/contact: ContactSolver, Polonsky–Keer with DC-FFT products, D-6, D-7) on a numpy gap map,
// with the options of the study keys [stiffness] hardness, tolerance and max_iterations.
#include <cmath>
#include <limits>
#include <optional>

#include "kernels/contact/contact_solver.hpp"
#include "kernels/contact/geometry.hpp"
#include "python/bindings.hpp"
#include "src/io/number_text.hpp"
#include "src/study/sections/stiffness_section.hpp"

namespace rollspec::python {

namespace {

double positive(const std::string& name, double v, const std::string& unit) {
  if (!(v > 0.0) || !std::isfinite(v))
    refuse(name, io::number_text(v), "not a size", "a finite number > 0 (" + unit + ")");
  return v;
}

contact::Grid grid_of(const Array& a, double dx, std::optional<double> dy) {
  contact::Grid g;
  g.ny = static_cast<std::size_t>(a.shape(0));
  g.nx = static_cast<std::size_t>(a.shape(1));
  g.dx = positive("dx", dx, "m");
  g.dy = positive("dy", dy.value_or(dx), "m");
  return g;
}

py::array_t<bool> cells_where(const std::vector<double>& p, const contact::Grid& g, double at_least) {
  py::array_t<bool> out({static_cast<py::ssize_t>(g.ny), static_cast<py::ssize_t>(g.nx)});
  bool* o = out.mutable_data();
  for (std::size_t i = 0; i < p.size(); ++i) o[i] = p[i] >= at_least && p[i] > 0.0;
  return out;
}

py::dict solve(const py::handle& gap, double dx, double e_star, std::optional<double> dy,
               std::optional<double> approach, std::optional<double> force, double hardness, double tolerance,
               long long max_iterations, bool stiffness) {
  const auto keys = study::StiffnessSection::keys();
  key_value(key_spec(keys, "stiffness.hardness"), hardness);
  key_value(key_spec(keys, "stiffness.tolerance"), tolerance);
  key_value(key_spec(keys, "stiffness.max_iterations"), static_cast<double>(max_iterations));
  positive("e_star", e_star, "Pa, the effective modulus E*");
  const Array s = finite_array(gap, "gap", 2, 1, "a 2-D array (ny, nx) of the undeformed gap (m), finite");
  const contact::Grid grid = grid_of(s, dx, dy);
  if (approach.has_value() == force.has_value())
    refuse("approach, force", approach ? "both given" : "neither given", "one control",
           "exactly one: approach (m, displacement control) or force (N, load control)");
  contact::SolverOptions options;
  options.hardness = hardness > 0.0 ? hardness : std::numeric_limits<double>::infinity();  // as [stiffness] reads it
  options.tolerance = tolerance;
  options.max_iterations = static_cast<int>(max_iterations);
  options.compute_stiffness = stiffness;
  if (approach && !std::isfinite(*approach))
    refuse("approach", io::number_text(*approach), "not finite", "a finite approach (m) from the gap's zero");
  if (force) {
    const double most = options.hardness * grid.cell_area() * static_cast<double>(grid.size());
    if (!(*force >= 0.0) || !std::isfinite(*force))
      refuse("force", io::number_text(*force), "not a load", "a finite force >= 0 (N)");
    if (*force > most)
      refuse("force", io::number_text(*force) + " N", "more than the grid can carry at the hardness",
             "at most hardness x grid area = " + io::number_text(most) + " N");
  }
  std::vector<double> s_values(s.data(), s.data() + s.size()), pressure, u(grid.size());
  contact::ContactResult r;
  {
    py::gil_scoped_release unlocked;
    contact::ContactSolver solver(grid, e_star);
    r = approach ? solver.solve(s_values, *approach, pressure, options)
                 : solver.solve_at_force(s_values, *force, pressure, options);
    solver.half_space().apply(pressure.data(), u.data());
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = s_values[i] - r.approach + u[i];  // g = s - w + C p (Eq. 6)
  }
  py::dict d;
  d["contact"] = cells_where(pressure, grid, 0.0);
  d["plastic"] = cells_where(pressure, grid, options.hardness);
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(grid.ny), static_cast<py::ssize_t>(grid.nx)};
  d["pressure"] = to_numpy(std::move(pressure), shape);
  d["gap"] = to_numpy(std::move(u), shape);
  d["force"] = r.force;
  d["approach"] = r.approach;
  d["contact_area"] = r.contact_area;
  d["contact_cells"] = r.contact_cells;
  d["plastic_cells"] = r.plastic_cells;
  d["plastic_volume"] = r.plastic_volume;
  d["max_pressure"] = r.max_pressure;
  d["iterations"] = r.iterations;
  d["coarse_iterations"] = r.coarse_iterations;
  d["residual"] = r.error;
  d["converged"] = r.converged;
  d["stiffness"] = r.stiffness;
  d["frozen_stiffness"] = r.frozen_stiffness;
  d["stiffness_converged"] = r.stiffness_converged;
  return d;
}

py::array_t<double> ball_gap(double radius, double dx, long long nx, long long ny, std::optional<double> dy,
                             const std::string& shape) {
  positive("radius", radius, "m");
  if (nx < 1 || ny < 1)
    refuse("nx, ny", std::to_string(nx) + ", " + std::to_string(ny), "not a grid", "whole numbers >= 1 (cells)");
  contact::BallShape b = contact::BallShape::Sphere;
  std::string allowed;
  bool found = false;
  for (const auto& c : study::kBallShapes) {
    if (shape == c.spelling) b = c.value, found = true;
    allowed += (allowed.empty() ? "" : ", ") + std::string(c.spelling);
  }
  if (!found) refuse("shape", "'" + shape + "'", "unknown ball shape", allowed);
  contact::Grid g{static_cast<std::size_t>(nx), static_cast<std::size_t>(ny), 0.0, 0.0};
  g.dx = positive("dx", dx, "m");
  g.dy = positive("dy", dy.value_or(dx), "m");
  return to_numpy(contact::ball_gap(g, radius, {}, b), {ny, nx});
}

const char* const kSolveDoc = R"(Contact of a rough surface on an elastic half-space, elastic or elastic-plastic.

Solves the contact conditions (D-7) for the undeformed gap s on a grid of cells dx x dy:

    g = s - w + C p,   0 <= p <= H,   g >= 0 and p g = 0 where p < H,   g <= 0 where p = H,

C the half-space's Love coefficients (D-6) applied by DC-FFT products, by the constrained conjugate
gradients of Polonsky & Keer (1999) with the pressure cap H (the command's stiffness tables'
solver). In displacement control the rigid approach w is given; in load control the total force
F = dx dy sum(p), and w is found. The grid is centred on the origin, x along axis 1.

Parameters
----------
gap : array_like, shape (ny, nx)
    Undeformed gap s (m) between the bodies at w = 0: first contact at w = min(s). For a rigid flat
    pressed on a height map h, s = max(h) - h; for a ball, `ball_gap` (minus the heights).
    C-contiguous float64 is read as it is (one copy into the solver); anything else is converted.
dx : float
    Cell size along x (m).
e_star : float
    Effective modulus E* (Pa): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (`effective_modulus`).
dy : float, optional
    Cell size along y (m); default dx.
approach : float, optional
    Rigid approach w (m), measured as s is: displacement control.
force : float, optional
    Total force F (N): load control. Give exactly one of approach and force.
hardness : float
    Pressure cap H (Pa), plastic flow; 0: none (elastic). The study key [stiffness] hardness, its
    default and range.
tolerance : float
    Stopping rule: the relative complementarity error (kernels/contact README Eq. 9) below this;
    [stiffness] tolerance, its default and range.
max_iterations : int
    CG iterations allowed; [stiffness] max_iterations, its default and range.
stiffness : bool
    Also the contact stiffness dF/dw (N/m) of the frozen contact set with its sub-cell edge
    (README Eq. 11, 13-15); displacement control only (NaN in load control).

Returns
-------
dict
    pressure (Pa), gap (m, the loaded gap g), contact (bool, p > 0), plastic (bool, p = H), each
    (ny, nx); force (N), approach (m), contact_area (m^2), contact_cells, plastic_cells,
    plastic_volume (m^3), max_pressure (Pa), iterations, coarse_iterations, residual (the error of
    README Eq. 9 at the returned field), converged (False: max_iterations reached; the fields are
    the last iterate), stiffness and frozen_stiffness (N/m), stiffness_converged.

Raises
------
ValueError
    A bad option or array (NaN, wrong shape or dtype), one line naming it, its value and what is
    allowed.

The interpreter lock is released while the solver runs.
)";

const char* const kBallGapDoc =
    R"(Undeformed gap of a smooth ball on a flat (kernels/contact README Eq. 5), shape (ny, nx).

s = z(r) with z = R - sqrt(R^2 - r^2) ('sphere') or r^2 / (2 R) ('paraboloid', Hertz's), r the
distance (m) of each cell centre from the grid's centre; cells dx x dy (m), dy default dx. Subtract a
rough flat's heights h (m, up positive) for a ball on that flat: s - h.
)";

}  // namespace

void bind_contact(py::module_& m) {
  using py::arg;
  const auto keys = study::StiffnessSection::keys();
  m.def("solve", &solve, kSolveDoc, arg("gap"), arg("dx"), py::kw_only(), arg("e_star"), arg("dy") = py::none(),
        arg("approach") = py::none(), arg("force") = py::none(),
        arg("hardness") = key_default(key_spec(keys, "stiffness.hardness")),
        arg("tolerance") = key_default(key_spec(keys, "stiffness.tolerance")),
        arg("max_iterations") = static_cast<long long>(key_default(key_spec(keys, "stiffness.max_iterations"))),
        arg("stiffness") = true);
  m.def("ball_gap", &ball_gap, kBallGapDoc, arg("radius"), arg("dx"), arg("nx"), arg("ny"), py::kw_only(),
        arg("dy") = py::none(), arg("shape") = "sphere");
  m.def(
      "effective_modulus",
      [](double e1, double nu1, double e2, double nu2) { return contact::effective_modulus(e1, nu1, e2, nu2); },
      "Effective modulus E* (Pa) of two elastic bodies (D-6): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, E in Pa.",
      arg("e1"), arg("nu1"), arg("e2"), arg("nu2"));
}

}  // namespace rollspec::python
