#include "src/io/csv_layout.hpp"

#include <cstdlib>

#include "src/io/measurement_unit.hpp"
#include "src/text_trim.hpp"

namespace rollspec::io {

CsvLayoutFinder::Shape CsvLayoutFinder::shape(const std::string& line, char delimiter, int file_line) {
  Shape s;
  s.line = file_line;
  const auto cells = split_cells(line, delimiter);
  s.cells = cells.size();
  s.numeric = !cells.empty();
  for (const auto& c : cells) {
    const bool number = numeric_cell(c, delimiter != ',');
    s.numeric = s.numeric && number;
    s.any_number = s.any_number || number;
    s.any_empty = s.any_empty || c.empty();
  }
  if (!s.numeric) s.text = line;
  s.has_delimiter = delimiter != 0 && line.find(delimiter) != std::string::npos;
  s.has_comma = line.find(',') != std::string::npos;
  return s;
}

bool CsvLayoutFinder::units_row(const Shape& s, char delimiter) {
  if (s.numeric) return false;
  bool known = false;  // a section line such as "[Data]" is bracketed, but no unit
  for (const auto& c : split_cells(s.text, delimiter)) {
    if (!units_row_cell(c)) return false;
    known = known || parse_measurement_unit(c).has_value();
  }
  return known;
}

// A line after numeric rows of its width heads a table only if it holds names alone: with a number
// in it, it is a bad data row, and its error is reported at its line rather than hidden as a preamble.
bool CsvLayoutFinder::Tracker::may_head(const Shape& h, std::size_t index, bool first_only) const {
  if (first_only && index != 0) return false;
  if (h.numeric) return false;
  return widths.count(h.cells) == 0 || !(h.any_number || h.any_empty);
}

void CsvLayoutFinder::Tracker::close() {
  if (active && (!best.found || run.rows > best.rows)) {
    best = run;
    best_header = run_header;
  }
  active = false;
}

void CsvLayoutFinder::Tracker::add(const Shape& s, bool first_only) {
  const std::size_t i = seen++;
  if (!s.numeric) {
    close();
  } else if (active && s.cells == run_header.cells) {
    ++run.rows;
  } else {
    close();
    // the header just above, or two lines up with a units row between (or a units row just above it)
    if (i >= 1 && !prev1.numeric && prev1.cells == s.cells) {
      const bool two = i >= 2 && !prev2.numeric && prev2.cells == s.cells;
      CsvLayout c;
      c.found = true;
      c.delimiter = delimiter;
      c.rows = 1;
      c.rows_before = numeric_rows;
      const bool units1 = units_row(prev1, delimiter), units2 = two && units_row(prev2, delimiter);
      if (two && units1 && !units2 && may_head(prev2, i - 2, first_only)) {
        c.header = i - 2;
        c.header_line = prev2.line;
        c.units_row = true;
        c.units = i - 1;
        c.units_line = prev1.line;
        run_header = prev2;
        active = true;
      } else if (may_head(prev1, i - 1, first_only)) {
        c.header = i - 1;
        c.header_line = prev1.line;
        if (units2 && !units1 && !first_only) {
          c.units_row = true;
          c.units = i - 2;
          c.units_line = prev2.line;
        }
        run_header = prev1;
        active = true;
      }
      if (active) run = c;
    }
  }
  if (s.numeric) {
    ++numeric_rows;
    widths.insert(s.cells);
  }
  prev2 = prev1;
  prev1 = s;
}

void CsvLayoutFinder::add(const std::string& line, int file_line) {
  // A line without a tracker's delimiter is one cell for it, as for the one-column reading (0).
  const Shape whole = shape(line, 0, file_line);
  for (auto& t : trackers_)
    t.add(t.delimiter != 0 && line.find(t.delimiter) != std::string::npos ? shape(line, t.delimiter, file_line) : whole,
          first_only_);
}

CsvLayout CsvLayoutFinder::result() const {
  CsvLayout best;
  for (std::size_t k = 0; k < trackers_.size(); ++k) {
    Tracker t = trackers_[k];
    t.close();
    if (!t.best.found) continue;
    if (t.delimiter == 0) {
      // one column with a decimal comma: only where ',' as a delimiter explains fewer rows, and the
      // header holds no ',' (a header with a comma says the commas delimit)
      if (!t.best_header.has_comma && (!best.found || (best.delimiter == ',' && t.best.rows > best.rows)))
        best = t.best;
      continue;
    }
    if (t.delimiter != ',' && !t.best_header.has_delimiter) continue;  // the same reading as ',' or none
    if (!best.found || t.best.rows > best.rows) best = t.best;
  }
  return best;
}

std::vector<std::string> split_cells(const std::string& line, char delimiter) {
  std::vector<std::string> out;
  const auto clean = [](const std::string& s) {
    std::string c = trim(s);
    // Spreadsheet exports quote names (and sometimes numbers): "Time (s)";"Acc".
    if (c.size() >= 2 && c.front() == '"' && c.back() == '"') c = trim(c.substr(1, c.size() - 2));
    return c;
  };
  if (delimiter == 0) return {clean(line)};
  for (std::size_t from = 0;;) {
    const auto at = line.find(delimiter, from);
    out.push_back(clean(line.substr(from, at == std::string::npos ? std::string::npos : at - from)));
    if (at == std::string::npos) break;
    from = at + 1;
  }
  if (line.empty()) out.clear();  // as getline: an empty line has no cell
  return out;
}

bool numeric_cell(const std::string& cell, bool comma_decimal) {
  std::string text = cell;
  if (comma_decimal && text.find('.') == std::string::npos)
    for (char& c : text)
      if (c == ',') c = '.';
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return !text.empty() && end != text.c_str() && *end == '\0';
}

}  // namespace rollspec::io
