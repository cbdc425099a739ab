#pragma once
// Tabulated one-sided PSD with log-log interpolation (README Eq. 5):
//
//   G(k) = G_i (k / k_i)^{s_i},  s_i = ln(G_{i+1}/G_i) / ln(k_{i+1}/k_i),  k_i <= k <= k_{i+1}
//
// A segment with a zero end value is interpolated linearly (log of zero is undefined).
// Outside [k_0, k_last] the table is an error unless an extension is given:
//   constant:  G(k) = G_0 below, G_last above;
//   power_law: the end segments' slopes s_0 and s_last continued (needs positive end values);
//   zero:      G(k) = 0.
// Validation (constructor, std::invalid_argument naming index and value): >= 2 points, equal
// lengths, abscissae finite, > 0 and strictly increasing, values finite and >= 0.
#include <cstddef>
#include <vector>

#include "kernels/texture/psd.hpp"

namespace rollspec::texture {

enum class Extension { error, constant, power_law, zero };

class TabulatedPsd {
 public:
  // wavenumber in rad/m, psd in m^3 (one-sided, per rad/m). Use psd_units.hpp to convert a
  // table given in cycles/m first (the engine does this from the file header).
  TabulatedPsd(std::vector<double> wavenumber, std::vector<double> psd, Extension extension = Extension::error);

  double operator()(double k) const;  // throws std::domain_error outside the table for Extension::error
  double k_min() const { return k_.front(); }
  double k_max() const { return k_.back(); }
  Extension extension() const { return extension_; }
  const std::vector<double>& wavenumber() const { return k_; }
  const std::vector<double>& values() const { return g_; }

  Psd to_psd() const;  // a copy of this table inside a Psd
  // The integral of Eq. 5 over [a, b] clipped to [k_min, k_max] (exact: a power law per segment,
  // linear where an end value is zero); the extensions are not integrated.
  double integral(double a, double b) const;

 private:
  std::vector<double> k_, g_;
  Extension extension_;
  double segment(std::size_t i, double k) const;  // interpolate in [k_i, k_{i+1}] (or beyond, power law)
};

}  // namespace rollspec::texture
