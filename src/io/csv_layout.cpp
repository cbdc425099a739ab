#include "src/io/csv_layout.hpp"

#include <cstdlib>
#include <sstream>
#include <unordered_set>

#include "src/text_trim.hpp"

namespace rollspec::io {

namespace {
struct LineShape {
  std::size_t cells = 0;
  bool numeric = false;
};

LineShape shape(const std::string& line, char delimiter) {
  const auto cells = split_cells(line, delimiter);
  bool numeric = !cells.empty();
  for (const auto& c : cells) numeric = numeric && numeric_cell(c, delimiter != ',');
  return {cells.size(), numeric};
}

CsvLayout best_header(const std::vector<std::string>& lines, char delimiter, bool first_only) {
  std::vector<LineShape> shapes;
  for (const auto& l : lines) shapes.push_back(shape(l, delimiter));
  // run[i]: numeric rows of line i's width right after line i (computed from the end: linear).
  const std::size_t n = lines.size();
  std::vector<std::size_t> run(n + 1, 0);
  std::vector<std::size_t> same(n + 1, 0);  // same[i]: numeric rows from i on with the width of row i
  for (std::size_t i = n; i-- > 0;)
    same[i] = shapes[i].numeric
                  ? 1 + (i + 1 < n && shapes[i + 1].numeric && shapes[i + 1].cells == shapes[i].cells ? same[i + 1] : 0)
                  : 0;
  CsvLayout best;
  best.delimiter = delimiter;
  // A line after rows of numbers of its own width is a bad data row, not a header: its error is
  // reported at its line, not hidden as a preamble.
  std::unordered_set<std::size_t> numbers_before;  // widths of the numeric rows seen so far
  for (std::size_t i = 0; i + 1 < n && (!first_only || i == 0); ++i) {
    const bool after_rows = numbers_before.count(shapes[i].cells) > 0;
    if (shapes[i].numeric) numbers_before.insert(shapes[i].cells);
    if (after_rows || shapes[i].numeric || !shapes[i + 1].numeric || shapes[i + 1].cells != shapes[i].cells) continue;
    if (!best.found || same[i + 1] > best.rows) {
      best.found = true;
      best.header = i;
      best.rows = same[i + 1];
    }
  }
  return best;
}
}  // namespace

std::vector<std::string> split_cells(const std::string& line, char delimiter) {
  std::vector<std::string> out;
  const auto clean = [](const std::string& s) {
    std::string c = trim(s);
    // Spreadsheet exports quote names (and sometimes numbers): "Time (s)";"Acc".
    if (c.size() >= 2 && c.front() == '"' && c.back() == '"') c = trim(c.substr(1, c.size() - 2));
    return c;
  };
  if (delimiter == 0) return {clean(line)};
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, delimiter)) out.push_back(clean(cell));
  if (!line.empty() && line.back() == delimiter) out.push_back("");
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

CsvLayout find_csv_layout(const std::vector<std::string>& lines, bool first_only) {
  if (lines.empty()) return {};
  const std::string& last = lines.back();
  const char delimiter = last.find('\t') != std::string::npos ? '\t' : last.find(';') != std::string::npos ? ';' : ',';
  CsvLayout best = best_header(lines, delimiter, first_only);
  if (delimiter == ',') {
    const CsvLayout one = best_header(lines, 0, first_only);
    // a header with a comma says the commas delimit
    if (one.found && one.rows > best.rows && lines[one.header].find(',') == std::string::npos) best = one;
  }
  return best;
}

}  // namespace rollspec::io
