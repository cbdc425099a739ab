// Reading a measured PSD (psd_csv.hpp): rollspec psd's CSV, with or without its sidecar, its older
// marker-line format, or a spreadsheet export of frequency_hz and a PSD column.
#include <cctype>
#include <filesystem>
#include <fstream>

#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/csv_table.hpp"
#include "src/io/measurement_unit.hpp"
#include "src/io/number_text.hpp"
#include "src/io/psd_csv.hpp"
#include "src/text_trim.hpp"

namespace rollspec::io {

namespace {
// A PSD column's title: its name and the PSD unit it states ("Acc [(m/s^2)^2/Hz]", "psd (g^2/Hz)").
// A bracket that holds "/Hz" is taken for a unit; any other bracket is part of the name.
struct Title {
  std::string base, written;
  std::optional<MeasurementUnit> unit;
  bool states_unit = false;
};

Title split_title(const std::string& title) {
  Title t{title, "", std::nullopt, false};
  const NamedUnit n = unit_in_name(title);
  if (!n.bracketed || n.written.empty()) return t;
  t.unit = parse_psd_unit(n.written);
  std::string lower;
  for (const char c : n.written) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  t.states_unit = t.unit || lower.find("/hz") != std::string::npos;
  if (!t.states_unit) return t;
  t.written = n.written;
  const char close = title.back(), open = close == ']' ? '[' : '(';
  for (std::size_t depth = 0, i = title.size(); i-- > 0;) {  // the bracket that opens the last pair
    if (title[i] == close) ++depth;
    if (title[i] == open && --depth == 0) {
      t.base = trim(title.substr(0, i));
      break;
    }
  }
  return t;
}

bool starts_with_marker(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first;
  std::getline(in, first);
  if (first.compare(0, 3, "\xEF\xBB\xBF") == 0) first.erase(0, 3);
  return first.rfind("# rollspec-psd-csv", 0) == 0;
}

std::string list(const CsvTable& m, const std::vector<std::size_t>& cols) {
  std::string s;
  for (const auto c : cols) s += (s.empty() ? "" : ", ") + m.columns[c];
  return clip(s, 400);
}

// The PSD column: --column by title, by title without its unit, or by the sidecar's channel; else
// `psd`; else in rollspec's own output (or where every title states a PSD unit) the only one.
std::size_t pick_column(const CsvTable& m, std::size_t fc, const std::string& column,
                        const std::optional<PsdSidecar>& side, bool rollspec_output, PsdCsv& out) {
  std::vector<std::size_t> psd_columns;
  for (std::size_t c = 0; c < m.columns.size(); ++c)
    if (c != fc) psd_columns.push_back(c);
  if (!column.empty()) {
    for (const auto c : psd_columns)
      if (m.columns[c] == column) return c;
    std::vector<std::size_t> match;
    for (const auto c : psd_columns) {
      bool same = split_title(m.columns[c]).base == column;
      if (side)
        for (const auto& s : side->columns)
          same = same || (s.title == m.columns[c] && (s.channel == column || s.name == column));
      if (same) match.push_back(c);
    }
    if (match.size() > 1)
      throw usage_error("--column " + clip(column) + ": names " + std::to_string(match.size()) + " columns of " +
                        m.file + " (" + list(m, match) + "); allowed: one of these titles");
    if (match.empty()) return m.column_index(column);  // the error naming the columns found
    out.notes.push_back(m.file + ": --column " + column + " is the column '" + m.columns[match[0]] + "'");
    return match[0];
  }
  for (const auto c : psd_columns)
    if (m.columns[c] == "psd") return c;
  bool stated = !psd_columns.empty();
  for (const auto c : psd_columns) stated = stated && split_title(m.columns[c]).states_unit;
  if (psd_columns.size() == 1 && (rollspec_output || stated)) {
    out.notes.push_back(m.file + ": the PSD is column '" + clip(m.columns[psd_columns[0]]) +
                        "', the only one besides frequency_hz (--column NAME picks another)");
    return psd_columns[0];
  }
  if (psd_columns.size() > 1) {
    std::string names;  // the channels, as --column takes them
    for (const auto c : psd_columns) names += (names.empty() ? "" : ", ") + split_title(m.columns[c]).base;
    throw usage_error(m.file + ": " + std::to_string(psd_columns.size()) + " PSD columns (" + clip(names, 400) +
                      (stated ? ", each titled with its unit" : "") +
                      ") and no --column; allowed: --column NAME to pick one");
  }
  std::vector<std::size_t> all(m.columns.size());
  for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
  throw data_error(m.file + ":" + std::to_string(m.header_line) + ": no column 'psd' in the header; columns found: " +
                   list(m, all) + "; allowed: a column named psd, or --column NAME");
}
}  // namespace

PsdCsv read_psd_csv(const std::string& path, const std::string& column, long long skip_rows) {
  CsvReadOptions options;
  options.find_header = true;
  options.skip_rows = skip_rows;
  const CsvTable m = read_csv(path, options);
  PsdCsv out;
  if (m.preamble_lines > 0)
    out.notes.push_back(path + ": skipped " +
                        counted(static_cast<unsigned long long>(m.preamble_lines), "preamble line") +
                        " before the header '" + clip(m.header_text) + "' (line " + std::to_string(m.header_line) +
                        "; --skip-rows N says where it is)");
  std::optional<PsdSidecar> side;
  const std::string side_path = psd_sidecar_path(path);
  std::error_code ec;
  if (std::filesystem::exists(side_path, ec)) {
    std::string why;
    side = read_psd_sidecar(side_path, sha256_file(path), why);
    if (!side) out.notes.push_back(path + ": its metadata " + side_path + " is ignored: " + why);
  }
  out.rollspec_output = side.has_value() || starts_with_marker(path);
  const std::size_t fc = m.column_index("frequency_hz");
  require_increasing(m, fc);
  const std::size_t pc = pick_column(m, fc, column, side, out.rollspec_output, out);
  out.column = m.columns[pc];
  const Title title = split_title(out.column);
  if (title.states_unit && !title.unit)
    throw data_error(path + ":" + std::to_string(m.header_line) + ": column '" + clip(out.column) + "' is in '" +
                     clip(title.written) +
                     "' by its title, which is no PSD of an acceleration; allowed: (m/s^2)^2/Hz, g^2/Hz, "
                     "(mm/s^2)^2/Hz, ... or no unit in the title ((m/s^2)^2/Hz)");
  const double factor = title.unit ? title.unit->factor : 1.0;
  if (factor != 1.0)
    out.notes.push_back(path + ": column '" + clip(out.column) + "' read in " + title.unit->text + " by its title (" +
                        number_text(factor) + " (m/s^2)^2/Hz each)");
  out.frequency = m.values[fc];
  out.psd = m.values[pc];
  for (std::size_t i = 0; i < out.frequency.size(); ++i)
    if (out.frequency[i] < 0.0)
      throw data_error(m.where(i) + ": frequency_hz value " + number_text(out.frequency[i]) +
                       " is negative; allowed: >= 0 (one-sided PSD)");
  for (std::size_t i = 0; i < out.psd.size(); ++i) {
    if (out.psd[i] < 0.0)
      throw data_error(m.where(i) + ": " + out.column + " value " + number_text(out.psd[i]) +
                       " is negative; allowed: >= 0");
    out.psd[i] *= factor;
  }
  if (side) {
    out.metadata = side->file;
    for (const auto& c : side->columns)
      if (c.title == out.column) out.metadata->column = c;
  }
  return out;
}

}  // namespace rollspec::io
