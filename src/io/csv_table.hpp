#pragma once
// Numeric CSV/text files with one header line: measured signals, PSD tables, measurements.
// The delimiter is taken from the header line: tab if it holds one, else ';' if it holds one, else ','.
// With ';' or tab a decimal comma is accepted (European loggers write `0,125;1,5`), but one file uses
// one decimal mark: a value with the other mark, or with both, is refused. CsvReadOptions::find_header
// (measured signals) also skips preamble lines before the header, reads a units row next to it and a
// one-column file with a decimal comma (csv_layout.hpp), and UTF-16 files with a byte-order mark
// (text_encoding.hpp). Names and values may be
// enclosed in double quotes (spreadsheet exports). Errors name the file, line, column and value
// (exit 65), or the missing file (exit 66).
#include <string>
#include <vector>

namespace rollspec::io {

struct CsvTable {
  std::string file;
  std::vector<std::string> columns;         // header names, trimmed
  std::vector<std::vector<double>> values;  // values[column][row]
  std::vector<int> lines;                   // file line of each row
  char delimiter = ',';                     // ',', ';', '\t', or 0: one column
  bool decimal_comma = false;               // true if the numbers were written with a decimal comma
  int header_line = 0;                      // file line of the header
  std::string header_text;                  // the header line as written
  int preamble_lines = 0;                   // lines skipped (found, not --skip-rows) before the header
  std::size_t preamble_rows = 0;            // numeric rows among them (a table in the preamble)
  bool layout_found = false;                // find_header: the header and delimiter came from the data rows
  std::vector<std::string> units;           // find_header: the units row's cells, one per column (none: empty)
  int units_line = 0;                       // its file line (0: no units row)
  std::string encoding;                     // "" (UTF-8 or ASCII), or "UTF-16LE"/"UTF-16BE" read as UTF-8
  // Printed precision of each column: most decimal places (fixed notation) and most significant digits
  // of any value; rounded time stamps are judged by them (time_column.hpp).
  std::vector<int> decimals, significant;

  std::size_t rows() const { return lines.size(); }
  std::size_t column_index(const std::string& name) const;  // throws data_error naming the columns found
  const std::vector<double>& column(const std::string& name) const { return values[column_index(name)]; }
  std::string where(std::size_t row) const { return file + ":" + std::to_string(lines[row]); }
};

struct CsvReadOptions {
  bool find_header = false;  // preamble lines, delimiter from the data rows, one-column decimal comma
  long long skip_rows = -1;  // >= 0: skip this many lines of the file, the next is the header
};

CsvTable read_csv(const std::string& path, const CsvReadOptions& options = {});

// The delimiter of a header line: '\t' if it holds a tab, else ';' if it holds one, else ','.
char detect_delimiter(const std::string& header);

// "comma", "semicolon", "tab", "none" (one column): for messages.
const char* delimiter_name(char delimiter);

// Checks that a column strictly increases (a frequency axis); throws data_error naming the row.
void require_increasing(const CsvTable& t, std::size_t column);

}  // namespace rollspec::io
