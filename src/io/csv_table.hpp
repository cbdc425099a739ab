#pragma once
// Numeric CSV/text files with one header line: measured signals, PSD tables, measurements.
// The delimiter is taken from the header line: tab if it holds one, else ';' if it holds one, else ','.
// With ';' a decimal comma is accepted (European loggers write `0,125;1,5`), but one file uses one
// decimal mark: a value with the other mark, or with both, is refused. Names and values may be
// enclosed in double quotes (spreadsheet exports). Errors name the file, line, column and value
// (exit 65), or the missing file (exit 66).
#include <string>
#include <vector>

namespace rollspec::io {

struct CsvTable {
  std::string file;
  std::vector<std::string> columns;          // header names, trimmed
  std::vector<std::vector<double>> values;   // values[column][row]
  std::vector<int> lines;                    // file line of each row
  char delimiter = ',';                      // ',', ';' or '\t'
  bool decimal_comma = false;                // true if the numbers were written with a decimal comma

  std::size_t rows() const { return lines.size(); }
  std::size_t column_index(const std::string& name) const;  // throws data_error naming the columns found
  const std::vector<double>& column(const std::string& name) const { return values[column_index(name)]; }
  std::string where(std::size_t row) const { return file + ":" + std::to_string(lines[row]); }
};

CsvTable read_csv(const std::string& path);

// The delimiter of a header line: '\t' if it holds a tab, else ';' if it holds one, else ','.
char detect_delimiter(const std::string& header);

// "comma", "semicolon", "tab": for messages.
const char* delimiter_name(char delimiter);

// Checks that a column strictly increases (a frequency axis); throws data_error naming the row.
void require_increasing(const CsvTable& t, std::size_t column);

}  // namespace rollspec::io
