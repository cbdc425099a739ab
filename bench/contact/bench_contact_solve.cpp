// One contact solve as rollspec.contact.solve makes it (python/contact_bindings.cpp, displacement
// control), in C++: the C++ side of bench/engine/bench_python_module.py, which times the same solve
// through the Python module. Same work as the binding's: the gap copied into the solver's vector, a
// ContactSolver made, solve(), the loaded gap g = s - w + C p (D-7); the options given as the binding
// passes them (hardness <= 0: none, as [stiffness] reads it). One untimed solve first (the Python side
// is warmed up the same way), then REPEATS timed: wall seconds of each solve only.
//
// Usage: bench_contact_solve GAP NX NY DX E_STAR APPROACH HARDNESS TOLERANCE MAX_ITERATIONS STIFFNESS REPEATS
//   GAP: ny x nx float64 values, row-major, native byte order (numpy's tofile). STIFFNESS: 0 or 1.
// Prints one line: seconds=S1,S2,... force=F iterations=N converged=C (F in C99 hex, bit for bit; the
// last solve's, each repeat's the same or it says so on stderr and exits 70).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "kernels/contact/contact_solver.hpp"

using namespace rollspec::contact;

namespace {

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "bench_contact_solve: error: %s\n", why.c_str());
  std::exit(64);
}

double number(const char* text, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') usage(std::string(what) + " '" + text + "' is not a number");
  return v;
}

struct Solved {
  ContactResult result;
  double seconds = 0.0;
};

// What the binding's released section does, timed.
Solved solve_once(const std::vector<double>& gap, const Grid& grid, double e_star, double approach,
                  const SolverOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> s_values(gap.begin(), gap.end()), pressure, u(grid.size());
  ContactSolver solver(grid, e_star);
  Solved out;
  out.result = solver.solve(s_values, approach, pressure, options);
  solver.half_space().apply(pressure.data(), u.data());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = s_values[i] - out.result.approach + u[i];
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 12)
    usage(
        "usage: bench_contact_solve GAP NX NY DX E_STAR APPROACH HARDNESS TOLERANCE MAX_ITERATIONS STIFFNESS "
        "REPEATS");
  Grid grid;
  grid.nx = static_cast<std::size_t>(number(argv[2], "NX"));
  grid.ny = static_cast<std::size_t>(number(argv[3], "NY"));
  grid.dx = grid.dy = number(argv[4], "DX");
  const double e_star = number(argv[5], "E_STAR"), approach = number(argv[6], "APPROACH");
  const double hardness = number(argv[7], "HARDNESS");
  SolverOptions options;
  options.hardness = hardness > 0.0 ? hardness : std::numeric_limits<double>::infinity();
  options.tolerance = number(argv[8], "TOLERANCE");
  options.max_iterations = static_cast<int>(number(argv[9], "MAX_ITERATIONS"));
  options.compute_stiffness = number(argv[10], "STIFFNESS") != 0.0;
  const int repeats = static_cast<int>(number(argv[11], "REPEATS"));
  if (repeats < 1) usage("REPEATS must be >= 1");
  std::vector<double> gap(grid.size());
  std::ifstream in(argv[1], std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(gap.data()), static_cast<std::streamsize>(gap.size() * sizeof(double))) ||
      in.peek() != std::char_traits<char>::eof())
    usage(std::string("GAP '") + argv[1] + "': not " + std::to_string(gap.size()) + " float64 values");
  const Solved first = solve_once(gap, grid, e_star, approach, options);  // warm-up, untimed
  std::string seconds;
  for (int r = 0; r < repeats; ++r) {
    const Solved s = solve_once(gap, grid, e_star, approach, options);
    if (s.result.force != first.result.force) {
      std::fprintf(stderr, "bench_contact_solve: error: repeat %d gave force %a, the first %a\n", r + 1, s.result.force,
                   first.result.force);
      return 70;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%s%.9f", r ? "," : "", s.seconds);
    seconds += text;
  }
  std::printf("seconds=%s force=%a iterations=%d converged=%d\n", seconds.c_str(), first.result.force,
              first.result.iterations, first.result.converged ? 1 : 0);
  return 0;
}
