#pragma once
// Numeric CSV files with one header line: measured signals, PSD tables, measurements.
// Errors name the file, line, column and value (exit 65), or the missing file (exit 66).
#include <string>
#include <vector>

namespace rollspec::io {

struct CsvTable {
  std::string file;
  std::vector<std::string> columns;          // header names, trimmed
  std::vector<std::vector<double>> values;   // values[column][row]
  std::vector<int> lines;                    // file line of each row

  std::size_t rows() const { return lines.size(); }
  std::size_t column_index(const std::string& name) const;  // throws data_error naming the columns found
  const std::vector<double>& column(const std::string& name) const { return values[column_index(name)]; }
  std::string where(std::size_t row) const { return file + ":" + std::to_string(lines[row]); }
};

CsvTable read_csv(const std::string& path);

// Checks that a column strictly increases (a frequency axis); throws data_error naming the row.
void require_increasing(const CsvTable& t, std::size_t column);

}  // namespace rollspec::io
