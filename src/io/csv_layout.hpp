#pragma once
// Where the header of a logger export is and how its cells are split (forgiving import, `rollspec psd`):
// loggers write preamble lines (name, date, units) before the header, and a one-column export with a
// decimal comma (`0,0123`) looks like two comma-delimited integers. pandas needs skiprows, sep and
// decimal spelled out; here they are found from the first lines, and each choice is reported.
#include <cstddef>
#include <string>
#include <vector>

namespace rollspec::io {

struct CsvLayout {
  bool found = false;      // false: no line is followed by numeric rows of its own width
  std::size_t header = 0;  // index of the header among the lines given
  char delimiter = ',';    // ',', ';', '\t', or 0: one column, nothing to split
  std::size_t rows = 0;    // numeric rows of the header's width that follow it (among the lines given)
};

// The lines (non-blank, non-comment, in file order) from the start of the data or after --skip-rows.
// The header is the non-numeric line followed by the longest run of numeric rows of its width (the
// earliest on ties; only the first line if `first_only`). The delimiter is the data's: tab if the
// last line holds one, else ';' if it does, else ','; with ',' a one-column reading with a decimal
// comma is taken if it explains strictly more rows.
CsvLayout find_csv_layout(const std::vector<std::string>& lines, bool first_only);

// Cells of a line: split on `delimiter` (0: the whole line), trimmed, double quotes removed.
std::vector<std::string> split_cells(const std::string& line, char delimiter);

// A cell that reads as a finite or infinite number (a decimal comma allowed where `comma_decimal`).
bool numeric_cell(const std::string& cell, bool comma_decimal);

}  // namespace rollspec::io
