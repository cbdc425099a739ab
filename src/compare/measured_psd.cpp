#include "src/compare/measured_psd.hpp"

#include <cmath>
#include <iostream>

#include "src/error.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::compare {

Measurement read_measurement(const std::string& path, std::string& column, long long skip_rows,
                             const std::string& command) {
  io::PsdCsv m = io::read_psd_csv(path, column, skip_rows);
  for (const auto& note : m.notes) std::cerr << "rollspec " << command << ": " << note << "\n";
  column = m.column;
  return Measurement{std::move(m.frequency), std::move(m.psd), std::move(m.metadata)};
}

void check_frequency_range(double fmin, double fmax) {
  if (!(fmin >= 0.0) || std::isinf(fmin))
    throw usage_error("--fmin " + io::number_text(fmin) + ": allowed: a finite frequency >= 0 Hz");
  if (!(fmax > fmin))
    throw usage_error("--fmax " + io::number_text(fmax) + ": allowed: a frequency above --fmin (" +
                      io::number_text(fmin) + " Hz)");
}

}  // namespace rollspec::compare
