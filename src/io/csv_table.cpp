#include "src/io/csv_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "src/error.hpp"
#include "src/io/input_file.hpp"

namespace rollspec::io {

namespace {
std::string trim(const std::string& s, const char* blanks = " \t\r") {
  const auto b = s.find_first_not_of(blanks);
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

// Spreadsheet exports quote names (and sometimes numbers): "Time (s)";"Acc".
std::string unquote(const std::string& s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return trim(s.substr(1, s.size() - 2));
  return s;
}

std::vector<std::string> split(const std::string& line, char delimiter) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, delimiter)) out.push_back(unquote(trim(cell)));
  if (!line.empty() && line.back() == delimiter) out.push_back("");
  return out;
}

// With ';' both decimal marks occur in practice, and a file mixing them (or a value holding both: a
// thousands separator) would be misread one way or the other, so the first value that shows a mark
// fixes it for the file.
struct DecimalMark {
  char mark = 0;  // '.' or ',' once a value has shown one
  int line = 0;
  std::string column;
};

const char* mark_name(char mark) { return mark == ',' ? "comma" : "point"; }

double parse_number(const std::string& cell, char delimiter, DecimalMark& dm, const std::string& path, int line,
                    const std::string& column) {
  const auto refuse = [&](const std::string& why) {
    return data_error(path + ":" + std::to_string(line) + ": column '" + clip(column) + "' value '" + clip(cell) + "' " + why);
  };
  std::string text = cell;
  if (delimiter == ';') {
    const auto comma = cell.find(','), point = cell.find('.');
    if (comma != std::string::npos && point != std::string::npos)
      throw refuse("holds both ',' and '.'; allowed: one decimal mark and no thousands separator, e.g. 1234,5 or 1234.5");
    const char used = comma != std::string::npos ? ',' : point != std::string::npos ? '.' : 0;
    if (used != 0 && dm.mark != 0 && used != dm.mark)
      throw refuse(std::string("has a decimal ") + mark_name(used) + ", but this file writes a decimal " + mark_name(dm.mark) +
                   " (line " + std::to_string(dm.line) + ", column '" + clip(dm.column) + "'); allowed: one decimal mark in a file");
    if (used != 0 && dm.mark == 0) dm = DecimalMark{used, line, column};
    if (used == ',') text[comma] = '.';
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0')
    throw refuse(delimiter == ';' ? "is not a number; allowed: a decimal number such as 1.5e-3 or 1,5e-3"
                                  : "is not a number; allowed: a decimal number such as 1.5e-3");
  if (!std::isfinite(v)) throw refuse("is not finite; allowed: finite numbers");
  return v;
}
}  // namespace

char detect_delimiter(const std::string& header) {
  if (header.find('\t') != std::string::npos) return '\t';
  if (header.find(';') != std::string::npos) return ';';
  return ',';
}

const char* delimiter_name(char delimiter) {
  return delimiter == '\t' ? "tab" : delimiter == ';' ? "semicolon" : "comma";
}

std::size_t CsvTable::column_index(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  std::string found;
  for (const auto& c : columns) found += (found.empty() ? "" : ", ") + c;
  throw data_error(file + ":1: no column '" + clip(name) + "' in the header; columns found: " + clip(found));
}

CsvTable read_csv(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw missing_input("cannot read '" + path + "': it is a directory; expected a CSV file");
  require_regular_input(path, "CSV file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw missing_input("cannot open '" + path + "'");
  CsvTable t;
  t.file = path;
  std::string line;
  int n = 0;
  DecimalMark mark;
  while (std::getline(in, line)) {
    ++n;
    // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
    if (n == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    // Control characters other than tab and carriage return mean binary data, not text.
    for (const char ch : line) {
      const auto u = static_cast<unsigned char>(ch);
      if ((u < 0x20 && ch != '\t' && ch != '\r') || u == 0x7f)
        throw data_error(path + ":" + std::to_string(n) + ": binary data (byte " + std::to_string(u) +
                         "); expected CSV text");
    }
    // Tabs may delimit cells, so only spaces and carriage returns are trimmed from the line itself.
    const std::string s = trim(line, " \r");
    if (trim(s).empty() || s[0] == '#') continue;
    if (t.columns.empty()) t.delimiter = detect_delimiter(s);
    const auto cells = split(s, t.delimiter);
    if (t.columns.empty()) {
      for (const auto& c : cells) {
        std::string number = c;  // a header of numbers is data without a header, decimal comma or not
        if (t.delimiter == ';') std::replace(number.begin(), number.end(), ',', '.');
        char* end = nullptr;
        std::strtod(number.c_str(), &end);
        if (!number.empty() && end != number.c_str() && *end == '\0')
          throw data_error(path + ":" + std::to_string(n) + ": the first line must be a header naming the columns, found the number '" +
                           clip(c) + "'");
        if (c.empty())
          throw data_error(path + ":" + std::to_string(n) + ": empty column name in the header (" + delimiter_name(t.delimiter) +
                           "-delimited); allowed: a name for every column, no trailing delimiter");
      }
      std::unordered_map<std::string, std::size_t> seen;  // linear: 300k columns must not take a minute
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto [it, fresh] = seen.emplace(cells[i], i);
        if (!fresh)
          throw data_error(path + ":" + std::to_string(n) + ": column '" + clip(cells[i]) + "' appears twice in the header (columns " +
                           std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + "); each column name may appear once");
      }
      t.columns = cells;
      t.values.assign(cells.size(), {});
      continue;
    }
    if (cells.size() != t.columns.size())
      throw data_error(path + ":" + std::to_string(n) + ": " + std::to_string(cells.size()) + " values, but the header names " +
                       std::to_string(t.columns.size()) + " columns (" + delimiter_name(t.delimiter) +
                       "-delimited, from the header); allowed: one value per column");
    for (std::size_t c = 0; c < cells.size(); ++c)
      t.values[c].push_back(parse_number(cells[c], t.delimiter, mark, path, n, t.columns[c]));
    t.lines.push_back(n);
  }
  // getline stops on a read error, or a line it cannot hold in memory (bad_alloc is swallowed by the
  // stream), exactly as at the end of the file: only eof() tells them apart. Never drop the rest.
  if (!in.eof() || in.bad())
    throw data_error(path + ":" + std::to_string(n + 1) + ": cannot read this line (a read error, or a line too long " +
                     "to hold in memory); the data after it were not read; allowed: CSV text with lines of sensible length");
  if (t.columns.empty()) throw data_error(path + ": empty file; expected a header line and data rows");
  if (t.lines.empty()) throw data_error(path + ": header but no data rows; expected at least one row of numbers after the header");
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
