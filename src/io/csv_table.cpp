#include "src/io/csv_table.hpp"

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
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}
}  // namespace

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
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    const auto cells = split(s);
    if (t.columns.empty()) {
      for (const auto& c : cells) {
        char* end = nullptr;
        std::strtod(c.c_str(), &end);
        if (!c.empty() && end != c.c_str() && *end == '\0')
          throw data_error(path + ":" + std::to_string(n) + ": the first line must be a header naming the columns, found the number '" +
                           clip(c) + "'");
        if (c.empty()) throw data_error(path + ":" + std::to_string(n) + ": empty column name in the header");
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
                       std::to_string(t.columns.size()) + " columns; allowed: one value per column");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || end == cells[c].c_str() || *end != '\0')
        throw data_error(path + ":" + std::to_string(n) + ": column '" + clip(t.columns[c]) + "' value '" + clip(cells[c]) +
                         "' is not a number; allowed: a decimal number such as 1.5e-3");
      if (!std::isfinite(v))
        throw data_error(path + ":" + std::to_string(n) + ": column '" + clip(t.columns[c]) + "' value '" + clip(cells[c]) +
                         "' is not finite; allowed: finite numbers");
      t.values[c].push_back(v);
    }
    t.lines.push_back(n);
  }
  // getline stops on a read error, or a line it cannot hold in memory (bad_alloc is swallowed by the
  // stream), exactly as at the end of the file: only eof() tells them apart. Never drop the rest.
  if (!in.eof() || in.bad())
    throw data_error(path + ":" + std::to_string(n + 1) + ": cannot read this line (a read error, or a line too long " +
                     "to hold in memory); the data after it were not read; allowed: CSV text with lines of sensible length");
  if (t.columns.empty()) throw data_error(path + ": empty file; expected a header line and data rows");
  if (t.lines.empty()) throw data_error(path + ": header but no data rows; expected at least one row of numbers after the header");
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
