#include "kernels/texture/measured_psd.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

namespace {
std::string g6(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
}  // namespace

UnresolvedCells unresolved_cells(const EstimatedPsd& e, double resolved_level) {
  UnresolvedCells u;
  const double jr = static_cast<double>(e.first_resolved);
  u.k_low = 0.5 * e.dk;
  u.k_cell = 1.5 * e.dk;
  u.k_resolved = (jr - 0.5) * e.dk;
  const double vu = e.unresolved_variance();
  u.level = std::min(resolved_level, vu / ((jr - 1.0) * e.dk));  // Eq. 45: c
  u.cell_level = u.level + (vu - u.level * (jr - 1.0) * e.dk) / e.dk;
  return u;
}

Psd measured_line_psd(const EstimatedPsd& e, Extension extension, const PsdBands& bands) {
  PsdBands b = bands;
  b.first_bin = e.first_resolved;
  const TabulatedPsd table = smoothed_psd_table(e, extension, b);  // starts at k_r (Eq. 35)
  const UnresolvedCells u = unresolved_cells(e, table.values().front());
  const double k_top = table.k_max();
  Psd p = table.to_psd();
  p.density = [table, u, extension, k_top](double k) {
    if (k >= u.k_resolved) return table(k);
    if (k >= u.k_cell) return u.level;
    if (k >= u.k_low) return u.cell_level;
    if (extension == Extension::zero) return 0.0;
    if (extension != Extension::error) return u.cell_level;  // constant, power_law: the flat cell continued
    throw std::domain_error("the measured profiles cover k = " + g6(u.k_low) + " .. " + g6(k_top) +
                            " rad/m (wavelengths up to twice their length); asked for k = " + g6(k) +
                            " rad/m and no extension is set");
  };
  p.support_min = extension == Extension::zero || extension == Extension::error ? u.k_low : 0.0;
  p.breakpoints.insert(p.breakpoints.begin(), {u.k_low, u.k_cell});  // k_r is the table's first node
  p.cell_average = true;                                             // Eq. 14b
  const double v = e.variance > 0.0 ? e.variance : 1.0;
  p.description = "measured profiles (" + std::to_string(e.profiles) + " x " + std::to_string(e.samples) +
                  " samples at " + g6(e.spacing) + " m): resolved from k = " + g6(u.k_resolved) + " rad/m (" +
                  g6(e.resolved_variance() / v) + " of the variance, band-averaged, Eq. 33-35), unresolved " +
                  g6(e.unresolved_variance() / v) + " below (Eq. 44-45)";
  return p;
}

}  // namespace rollspec::texture
