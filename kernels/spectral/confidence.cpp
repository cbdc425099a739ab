#include "kernels/spectral/confidence.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <stdexcept>

namespace rollspec::spectral {

IntervalFactors chi_square_interval(double dof, double level) {
  if (!(dof > 0.0)) throw std::invalid_argument("chi-square interval needs positive degrees of freedom");
  if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("confidence level must lie in (0, 1)");
  const boost::math::chi_squared dist(dof);
  const double alpha = 1.0 - level;
  return {dof / boost::math::quantile(dist, 1.0 - alpha / 2.0), dof / boost::math::quantile(dist, alpha / 2.0)};
}

}  // namespace rollspec::spectral
