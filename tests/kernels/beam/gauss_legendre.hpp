#pragma once
// Composite Gauss–Legendre quadrature for the beam tests (nodes by Newton on P_n).
#include <cmath>
#include <vector>

namespace rollspec::beam::test {

struct Quadrature {
  std::vector<double> x, w;
};

// n-point rule on each of `panels` equal panels of [a, b].
inline Quadrature gauss_legendre(int n, int panels, double a, double b) {
  std::vector<double> t(n), wt(n);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    t[i] = z;
    wt[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
  Quadrature q;
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p)
    for (int i = 0; i < n; ++i) {
      q.x.push_back(a + h * (p + 0.5 * (t[i] + 1.0)));
      q.w.push_back(0.5 * h * wt[i]);
    }
  return q;
}

}  // namespace rollspec::beam::test
