#include "src/io/csv_table.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "src/error.hpp"
#include "src/io/csv_layout.hpp"
#include "src/io/input_file.hpp"
#include "src/io/text_encoding.hpp"
#include "src/text_trim.hpp"

namespace rollspec::io {

namespace {
// With ';' both decimal marks occur in practice, and a file mixing them (or a value holding both: a
// thousands separator) would be misread one way or the other, so the first value that shows a mark
// fixes it for the file.
struct DecimalMark {
  char mark = 0;  // '.' or ',' once a value has shown one
  int line = 0;
  std::string column;
};

const char* mark_name(char mark) { return mark == ',' ? "comma" : "point"; }

// Digits as printed: decimal places in fixed notation (1.5e-3: 4) and significant digits (0.0120: 3).
struct Printed {
  int decimals = 0, significant = 0;
};

Printed printed(const std::string& text) {
  Printed p;
  const auto e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  // clamped: an exponent of a billion digits must not overflow (the value is refused or 0 anyway)
  const long exp_read = e == std::string::npos ? 0 : std::strtol(text.c_str() + e + 1, nullptr, 10);
  const int exponent = static_cast<int>(std::max(-100000L, std::min(100000L, exp_read)));
  const auto point = mantissa.find('.');
  bool leading = true;
  for (std::size_t i = 0; i < mantissa.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(mantissa[i]))) continue;
    if (point != std::string::npos && i > point) ++p.decimals;
    if (mantissa[i] != '0') leading = false;
    if (!leading) ++p.significant;
  }
  p.decimals -= exponent;
  return p;
}

double parse_number(const std::string& cell, char delimiter, DecimalMark& dm, const std::string& path, int line,
                    const std::string& column, Printed* digits) {
  const auto refuse = [&](const std::string& why) {
    return data_error(path + ":" + std::to_string(line) + ": column '" + clip(column) + "' value '" + clip(cell) +
                      "' " + why);
  };
  std::string text = cell;
  if (delimiter != ',') {
    const auto comma = cell.find(','), point = cell.find('.');
    if (comma != std::string::npos && point != std::string::npos)
      throw refuse(
          "holds both ',' and '.'; allowed: one decimal mark and no thousands separator, e.g. 1234,5 or 1234.5");
    const char used = comma != std::string::npos ? ',' : point != std::string::npos ? '.' : 0;
    if (used != 0 && dm.mark != 0 && used != dm.mark)
      throw refuse(std::string("has a decimal ") + mark_name(used) + ", but this file writes a decimal " +
                   mark_name(dm.mark) + " (line " + std::to_string(dm.line) + ", column '" + clip(dm.column) +
                   "'); allowed: one decimal mark in a file");
    if (used != 0 && dm.mark == 0) dm = DecimalMark{used, line, column};
    if (used == ',') text[comma] = '.';
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0')
    throw refuse(delimiter != ',' ? "is not a number; allowed: a decimal number such as 1.5e-3 or 1,5e-3"
                                  : "is not a number; allowed: a decimal number such as 1.5e-3");
  if (!std::isfinite(v)) throw refuse("is not finite; allowed: finite numbers");
  if (digits) *digits = printed(text);
  return v;
}
}  // namespace

char detect_delimiter(const std::string& header) {
  if (header.find('\t') != std::string::npos) return '\t';
  if (header.find(';') != std::string::npos) return ';';
  return ',';
}

const char* delimiter_name(char delimiter) {
  return delimiter == '\t' ? "tab" : delimiter == ';' ? "semicolon" : delimiter == 0 ? "none (one column)" : "comma";
}

std::size_t CsvTable::column_index(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  std::string found;
  for (const auto& c : columns) found += (found.empty() ? "" : ", ") + c;
  throw data_error(file + ":" + std::to_string(header_line) + ": no column '" + clip(name) +
                   "' in the header; columns found: " + clip(found));
}

namespace {
// Lines of a text file one at a time: line numbers, a byte-order mark dropped, binary data refused,
// blank and '#' lines passed over (unless `raw`).
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& path) : in_(in), path_(path) {}
  bool next(std::string& out, bool raw = false) {
    std::string line;
    while (std::getline(in_, line)) {
      ++n_;
      // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
      if (n_ == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
      // Control characters other than tab and carriage return mean binary data, not text.
      for (const char ch : line) {
        const auto u = static_cast<unsigned char>(ch);
        if ((u < 0x20 && ch != '\t' && ch != '\r') || u == 0x7f)
          throw data_error(path_ + ":" + std::to_string(n_) + ": binary data (byte " + std::to_string(u) +
                           "); expected CSV text");
      }
      // Tabs may delimit cells, so only spaces and carriage returns are trimmed from the line itself.
      out = trim(line, " \r");
      if (raw || !(trim(out).empty() || out[0] == '#')) return true;
    }
    // getline stops on a read error, or a line it cannot hold in memory (bad_alloc is swallowed by the
    // stream), exactly as at the end of the file: only eof() tells them apart. Never drop the rest.
    if (!in_.eof() || in_.bad())
      throw data_error(
          path_ + ":" + std::to_string(n_ + 1) + ": cannot read this line (a read error, or a line too long " +
          "to hold in memory); the data after it were not read; allowed: CSV text with lines of sensible length");
    return false;
  }
  int line() const { return n_; }

 private:
  std::istream& in_;
  std::string path_;
  int n_ = 0;
};

// The header line: names, no numbers, none twice.
void read_header(CsvTable& t, const std::string& s, int n) {
  const std::string& path = t.file;
  const auto cells = split_cells(s, t.delimiter);
  for (const auto& c : cells) {
    if (numeric_cell(c, t.delimiter != ','))  // a header of numbers is data without a header, decimal comma or not
      throw data_error(path + ":" + std::to_string(n) +
                       ": the first line must be a header naming the columns, found the number '" + clip(c) + "'");
    if (c.empty())
      throw data_error(path + ":" + std::to_string(n) + ": empty column name in the header (" +
                       delimiter_name(t.delimiter) +
                       "-delimited); allowed: a name for every column, no trailing delimiter");
  }
  std::unordered_map<std::string, std::size_t> seen;  // linear: 300k columns must not take a minute
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto [it, fresh] = seen.emplace(cells[i], i);
    if (!fresh)
      throw data_error(path + ":" + std::to_string(n) + ": column '" + clip(cells[i]) +
                       "' appears twice in the header (columns " + std::to_string(it->second + 1) + " and " +
                       std::to_string(i + 1) + "); each column name may appear once");
  }
  t.columns = cells;
  t.header_line = n;
  t.header_text = s;
  t.values.assign(cells.size(), {});
  t.decimals.assign(cells.size(), INT_MIN);
  t.significant.assign(cells.size(), 0);
}

void read_row(CsvTable& t, const std::string& s, int n, DecimalMark& mark) {
  const auto cells = split_cells(s, t.delimiter);
  if (cells.size() != t.columns.size())
    throw data_error(t.file + ":" + std::to_string(n) + ": " + std::to_string(cells.size()) +
                     " values, but the header names " + std::to_string(t.columns.size()) + " columns (" +
                     delimiter_name(t.delimiter) + "-delimited, from the " + (t.layout_found ? "data rows" : "header") +
                     "); allowed: one value per column");
  for (std::size_t c = 0; c < cells.size(); ++c) {
    Printed p;
    t.values[c].push_back(parse_number(cells[c], t.delimiter, mark, t.file, n, t.columns[c], &p));
    t.decimals[c] = std::max(t.decimals[c], p.decimals);
    t.significant[c] = std::max(t.significant[c], p.significant);
  }
  t.lines.push_back(n);
}

void skip_lines(LineReader& reader, const std::string& path, long long skip_rows) {
  std::string line;
  for (long long k = 0; k < skip_rows; ++k)
    if (!reader.next(line, true))
      throw data_error(path + ": --skip-rows " + std::to_string(skip_rows) + " skips the whole file (" +
                       std::to_string(reader.line()) +
                       " lines); allowed: fewer lines than the file holds, then a header and data");
}

// The whole file once, for its layout (csv_layout.hpp): where the header and units row are, the delimiter.
CsvLayout find_layout(std::istream& in, const std::string& path, const CsvReadOptions& options) {
  LineReader reader(in, path);
  skip_lines(reader, path, options.skip_rows);
  CsvLayoutFinder finder(options.skip_rows >= 0);
  std::string line;
  bool any = false;
  while (reader.next(line)) {
    finder.add(line, reader.line());
    any = true;
  }
  if (!any) throw data_error(path + ": empty file; expected a header line and data rows");
  return finder.result();
}
}  // namespace

CsvTable read_csv(const std::string& path, const CsvReadOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw missing_input("cannot read '" + path + "': it is a directory; expected a CSV file");
  require_regular_input(path, "CSV file");
  CsvTable t;
  t.file = path;
  const auto in = open_text(path, t.encoding);
  CsvLayout layout;
  if (options.find_header) {
    layout = find_layout(*in, path, options);
    in->clear();
    in->seekg(0);
  }
  LineReader reader(*in, path);
  skip_lines(reader, path, options.skip_rows);
  std::string line;
  if (!reader.next(line)) throw data_error(path + ": empty file; expected a header line and data rows");
  t.delimiter = detect_delimiter(line);
  if (layout.found) {  // else the first line is the header, and its errors are today's
    t.delimiter = layout.delimiter;
    t.layout_found = true;
    t.preamble_rows = layout.rows_before;
    while (reader.line() < layout.header_line) {
      if (reader.line() == layout.units_line)
        t.units = split_cells(line, t.delimiter);
      else
        ++t.preamble_lines;
      reader.next(line);
    }
  }
  DecimalMark mark;
  read_header(t, line, reader.line());
  if (layout.units_row && layout.units_line > layout.header_line) {
    reader.next(line);
    t.units = split_cells(line, t.delimiter);
  }
  if (!t.units.empty()) t.units_line = layout.units_line;
  while (reader.next(line)) read_row(t, line, reader.line(), mark);
  if (t.lines.empty())
    throw data_error(path + ": header but no data rows; expected at least one row of numbers after the header");
  t.decimal_comma = mark.mark == ',';
  return t;
}

void require_increasing(const CsvTable& t, std::size_t column) {
  const auto& v = t.values[column];
  for (std::size_t r = 1; r < v.size(); ++r)
    if (!(v[r] > v[r - 1])) {
      std::ostringstream s;
      s.precision(17);
      s << t.where(r) << ": column '" << t.columns[column] << "' value " << v[r]
        << " does not increase (previous row: " << v[r - 1] << "); allowed: strictly increasing values";
      throw data_error(s.str());
    }
}

}  // namespace rollspec::io
