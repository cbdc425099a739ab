#include "src/cli/measured_psd.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>

#include "src/cli/parse_options.hpp"
#include "src/error.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

using io::number_text;

Measurement read_measurement(const std::string& path, std::string& column, long long skip_rows,
                             const std::string& command) {
  io::CsvReadOptions options;
  options.find_header = true;
  options.skip_rows = skip_rows;
  const io::CsvTable m = io::read_csv(path, options);
  if (m.preamble_lines > 0)
    std::cerr << "rollspec " + command + ": " << path << ": skipped "
              << io::counted(static_cast<unsigned long long>(m.preamble_lines), "preamble line")
              << " before the header '" << clip(m.header_text) << "' (line " << m.header_line
              << "; --skip-rows N says where it is)\n";
  const std::size_t fc = m.column_index("frequency_hz");
  io::require_increasing(m, fc);
  if (column.empty()) {
    const auto& cols = m.columns;
    const bool has_psd = std::find(cols.begin(), cols.end(), "psd") != cols.end();
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    const bool psd_output = first.rfind("# rollspec-psd-csv", 0) == 0;
    column = has_psd || cols.size() != 2 || !psd_output ? "psd" : cols[fc == 0 ? 1 : 0];
    if (column != "psd")
      std::cerr << "rollspec " + command + ": " << path << ": the PSD is column '" << clip(column)
                << "', the only one besides frequency_hz (--column NAME picks another)\n";
  }
  Measurement out{m.values[fc], m.values[m.column_index(column)]};
  const std::string name = column;
  for (std::size_t i = 0; i < out.frequency.size(); ++i)
    if (out.frequency[i] < 0.0)
      throw data_error(m.where(i) + ": frequency_hz value " + number_text(out.frequency[i]) +
                       " is negative; allowed: >= 0 (one-sided PSD)");
  for (std::size_t i = 0; i < out.psd.size(); ++i)
    if (out.psd[i] < 0.0)
      throw data_error(m.where(i) + ": " + name + " value " + number_text(out.psd[i]) + " is negative; allowed: >= 0");
  return out;
}

}  // namespace rollspec::cli
