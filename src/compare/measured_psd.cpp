#include "src/compare/measured_psd.hpp"

#include <iostream>

namespace rollspec::compare {

Measurement read_measurement(const std::string& path, std::string& column, long long skip_rows,
                             const std::string& command) {
  io::PsdCsv m = io::read_psd_csv(path, column, skip_rows);
  for (const auto& note : m.notes) std::cerr << "rollspec " << command << ": " << note << "\n";
  column = m.column;
  return Measurement{std::move(m.frequency), std::move(m.psd), std::move(m.metadata)};
}

}  // namespace rollspec::compare
