#include "kernels/texture/time_signal.hpp"

#include <cmath>
#include <stdexcept>

#include "kernels/texture/psd_units.hpp"

namespace rollspec::texture {

namespace {
void check_speed(double speed) {
  if (!(speed > 0.0) || !std::isfinite(speed)) throw std::invalid_argument("rolling speed must be positive and finite");
}
}  // namespace

TimeSignal line_to_time_signal(std::vector<double> heights, double spacing, double speed) {
  check_speed(speed);
  if (!(spacing > 0.0)) throw std::invalid_argument("line spacing must be positive");
  return TimeSignal{time_step_from_spacing(spacing, speed), std::move(heights)};
}

std::function<double(double)> time_psd(const Psd& psd, double speed) {
  check_speed(speed);
  return [psd, speed](double f) { return psd_time_from_psd_k(psd(wavenumber_from_frequency(f, speed)), speed); };
}

}  // namespace rollspec::texture
