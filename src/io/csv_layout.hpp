#pragma once
// Where the header of a logger export is and how its cells are split (forgiving import, `rollspec psd`):
// loggers write preamble lines (name, date, units, a calibration table) before the header, a units row
// under it (`Time⇥Acceleration`, then `[s]⇥[m/s²]`), and a one-column export with a decimal comma
// (`0,0123`) looks like two comma-delimited integers. pandas needs skiprows, sep and decimal spelled
// out; here they are found from the whole file, and each choice is reported.
#include <array>
#include <cstddef>
#include <string>
#include <unordered_set>
#include <vector>

namespace rollspec::io {

struct CsvLayout {
  bool found = false;           // false: no line is followed by numeric rows of its own width
  std::size_t header = 0;       // index of the header among the lines given
  int header_line = 0;          // its line in the file
  bool units_row = false;       // a units row of the header's width next to it (above or below)
  std::size_t units = 0;        // its index among the lines given
  int units_line = 0;           // its line in the file
  char delimiter = ',';         // ',', ';', '\t', or 0: one column, nothing to split
  std::size_t rows = 0;         // numeric rows of the header's width that follow it
  std::size_t rows_before = 0;  // numeric rows before the header (a table in the preamble)
};

// Fed the lines (non-blank, non-comment, in file order) from the start of the data or after --skip-rows,
// one at a time, so that the whole file is looked at without being held. The header is the non-numeric
// line followed by the longest run of numeric rows of its width (the earliest on ties; only the first
// line if `first_only`), with a units row (every cell a unit, bracketed or empty, one at least a known
// unit) between them or just above it. A line after numeric rows of its width is a bad data row, never a header, if any
// of its cells is a number; a line of names there heads a second, longer table (a table in the preamble). The delimiter
// is the one whose header explains the most rows: tab, ';' and ',' in that order on ties, each only if the header holds
// it; one column with a decimal comma only if it explains strictly more rows than ',' and the header holds no ','.
class CsvLayoutFinder {
 public:
  explicit CsvLayoutFinder(bool first_only) : first_only_(first_only) {}
  void add(const std::string& line, int file_line);
  CsvLayout result() const;

 private:
  struct Shape {
    std::size_t cells = 0;
    bool numeric = false;     // every cell a number
    bool any_number = false;  // some cell a number
    bool any_empty = false;   // some cell empty
    std::string text;         // the line, if not numeric: a units row is looked for only next to data
    bool has_delimiter = false;
    bool has_comma = false;
    int line = 0;
  };
  struct Tracker {
    explicit Tracker(char d) : delimiter(d) {}
    char delimiter;
    Shape prev1, prev2;
    std::size_t seen = 0;  // lines so far
    bool active = false;   // the last line continued the run
    CsvLayout run, best;
    Shape run_header, best_header;
    std::size_t numeric_rows = 0;
    std::unordered_set<std::size_t> widths;  // widths of the numeric rows so far
    void add(const Shape& s, bool first_only);
    void close();
    bool may_head(const Shape& h, std::size_t index, bool first_only) const;
  };
  static Shape shape(const std::string& line, char delimiter, int file_line);
  // Every cell a unit, bracketed or empty, and at least one a unit of measurement_unit.hpp's list.
  static bool units_row(const Shape& s, char delimiter);

  bool first_only_;
  std::array<Tracker, 4> trackers_{Tracker{'\t'}, Tracker{';'}, Tracker{','}, Tracker{0}};
};

// Cells of a line: split on `delimiter` (0: the whole line), trimmed, double quotes removed.
std::vector<std::string> split_cells(const std::string& line, char delimiter);

// A cell that reads as a finite or infinite number (a decimal comma allowed where `comma_decimal`).
bool numeric_cell(const std::string& cell, bool comma_decimal);

}  // namespace rollspec::io
