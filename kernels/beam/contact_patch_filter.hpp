#pragma once
// Contact-patch filter (seed 001 §4: the point contact over-excites wavelengths shorter than the
// contact), README Eq. (B35): the roughness averaged over a contact length 2a,
//   h_a(x) = (1 / 2a) int_{x-a}^{x+a} h(s) ds,   a Hertz half-width a = sqrt(R delta),
// integrated exactly on the piecewise-linear interpolant of the samples (prefix sums), the window
// truncated at the ends of the record. contact_patch_average uses one fixed width (e.g. a at the
// static compression under the weight); PatchAverager (B38) evaluates the average at any width,
// which the exact-step integrator uses with the width of the previous step (an exact
// instantaneous a(delta(t)) would make the contact solve a fixed point in a). A sinusoid of
// wavenumber k is scaled by sin(k a) / (k a).
#include <cmath>
#include <vector>

#include "kernels/beam/uniform_samples.hpp"

namespace rollspec::beam {

UniformSamples contact_patch_average(const UniformSamples& h, double half_width);

// What contact_patch_average does to a sampled sinusoid of wavenumber k (|k| <= pi/dx), away from
// the record ends, README Eq. (B35a): the output samples are sum_n c_n h_{j+n} with
//   c_n = (1/2w) int_{-w}^{w} Lambda(u - n) du,   w = a/dx,  Lambda the hat of linear interpolation,
//   T(k) = sum_n c_n cos(n k dx)  ->  sin(ka)/(ka) sinc^2(k dx/2) + (aliases of order dx/a),
// i.e. the continuous patch filter times the linear interpolation's low-pass. Real, even in k.
double contact_patch_transfer(double k, double half_width, double dx);

// Patch average at any position and half-width (README B38), for the instantaneous contact
// length of the ball-on-beam integrator: prefix integral of the linear interpolant, built once
// per realisation. value = (1/2a) int_{x-a}^{x+a} h, derivative = (h(x+a) - h(x-a)) / 2a; for
// a below a tenth of the sample step, the point value and slope (Catmull–Rom, B13).
class PatchAverager {
 public:
  explicit PatchAverager(const UniformSamples& h);
  void evaluate(double x, double a, double& value, double& derivative) const;

 private:
  double prefix(double u) const;  // integral from origin, u in sample units
  const UniformSamples* h_;
  std::vector<double> s_;
};

}  // namespace rollspec::beam
