// The CSVW metadata file beside a PSD CSV (psd_csv.hpp): written and read with nlohmann/json.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "src/io/content_hash.hpp"
#include "src/io/measurement_unit.hpp"
#include "src/io/psd_csv.hpp"

namespace rollspec::io {

namespace {
using Json = nlohmann::ordered_json;
constexpr const char* kKind = "rollspec-psd-csv";
constexpr const char* kMarker = "# rollspec-psd-csv";

// No delimiter or quote in a title, and no '#', where numpy.genfromtxt's header would end.
std::string clean_title(std::string s) {
  for (char& c : s)
    if (c == ',' || c == ';' || c == '\t' || c == '"' || c == '#') c = '_';
  return s;
}

// A CSVW column name: letters, digits and '_' (URI template variable characters), not starting with '_'.
std::string identifier(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    const bool keep = (u < 128 && std::isalnum(u)) || c == '_';
    if (keep)
      out += c;
    else if (!out.empty() && out.back() != '_')
      out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || out.front() == '_') out = "c" + out;
  return out;
}

template <typename T>
T get(const Json& j, const char* key, T fallback) {
  const auto it = j.find(key);
  if (it == j.end()) return fallback;
  try {
    return it->get<T>();
  } catch (const Json::exception&) {
    return fallback;
  }
}
}  // namespace

std::string psd_sidecar_path(const std::string& csv_path) {
  // beside the file itself: a link to a PSD CSV shares its metadata
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::is_symlink(csv_path, ec)
                                         ? std::filesystem::canonical(csv_path, ec)
                                         : std::filesystem::path(csv_path);
  return (ec ? csv_path : real.string()) + "-metadata.json";
}

std::vector<std::string> psd_column_titles(const std::vector<std::string>& channels) {
  std::vector<std::string> bases;
  for (const auto& c : channels) {
    const NamedUnit n = unit_in_name(c);
    bases.push_back(clean_title(n.unit ? n.base : c));
  }
  std::vector<std::string> out;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    std::size_t same = 0;
    for (const auto& b : bases) same += b == bases[i];
    out.push_back((same > 1 ? clean_title(channels[i]) : bases[i]) + " [" + kPsdUnit + "]");
  }
  return out;
}

std::string psd_sidecar_json(const PsdCsvMetadata& m, const std::vector<PsdColumnMetadata>& columns,
                             const std::string& csv_name, const std::string& csv) {
  Json cols = Json::array();
  cols.push_back(
      {{"name", "frequency_hz"}, {"titles", "frequency_hz"}, {"datatype", "double"}, {"rollspec:unit", "Hz"}});
  std::set<std::string> names{"frequency_hz"};
  for (const auto& c : columns) {
    std::string name = identifier(c.name);
    for (int k = 2; !names.insert(name).second; ++k) name = identifier(c.name) + "_" + std::to_string(k);
    cols.push_back({{"name", name},
                    {"titles", c.title},
                    {"datatype", "double"},
                    {"rollspec:unit", kPsdUnit},
                    {"rollspec:channel", c.channel},
                    {"rollspec:signal_unit", c.signal_unit},
                    {"rollspec:signal_unit_origin", c.signal_unit_origin}});
  }
  Json j;
  j["@context"] = "http://www.w3.org/ns/csvw";
  j["url"] = csv_name;
  j["dc:title"] = "One-sided Welch PSD of " + m.source;
  j["tableSchema"] = {{"columns", cols}};
  j["rollspec:kind"] = kKind;
  j["rollspec:csv_sha256"] = sha256_hex(csv);
  j["rollspec:version"] = m.version;
  j["rollspec:psd_unit"] = m.unit;
  j["rollspec:sample_rate_hz"] = m.sample_rate;
  j["rollspec:rate_source"] = m.rate_source;
  j["rollspec:segment"] = m.segment;
  j["rollspec:overlap"] = m.overlap;
  j["rollspec:window"] = m.window;
  j["rollspec:detrend"] = m.detrend;
  j["rollspec:samples"] = m.samples;
  j["rollspec:segments"] = m.segments;
  j["rollspec:equivalent_dof"] = m.edof;
  j["rollspec:scale"] = m.scale;
  j["rollspec:source"] = m.source;
  j["rollspec:source_sha256"] = m.source_hash;
  return j.dump(1) + "\n";
}

std::optional<PsdSidecar> read_psd_sidecar(const std::string& sidecar_path, const std::string& csv_hash,
                                           std::string& why) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(sidecar_path, ec)) {
    why = "missing";
    return std::nullopt;
  }
  std::ifstream in(sidecar_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const Json j = Json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    why = "not JSON";
    return std::nullopt;
  }
  if (get<std::string>(j, "rollspec:kind", "") != kKind) {
    why = "not a rollspec psd sidecar (no \"rollspec:kind\": \"" + std::string(kKind) + "\")";
    return std::nullopt;
  }
  PsdSidecar s;
  s.csv_hash = get<std::string>(j, "rollspec:csv_sha256", "");
  if (!csv_hash.empty() && s.csv_hash != csv_hash) {
    why = "it records another SHA-256 of the CSV than the CSV has (edited after psd wrote it?)";
    return std::nullopt;
  }
  auto& f = s.file;
  f.unit = get<std::string>(j, "rollspec:psd_unit", kPsdUnit);
  f.sample_rate = get<double>(j, "rollspec:sample_rate_hz", 0.0);
  f.rate_source = get<std::string>(j, "rollspec:rate_source", "");
  f.segment = get<std::size_t>(j, "rollspec:segment", 0);
  f.overlap = get<std::size_t>(j, "rollspec:overlap", 0);
  f.window = get<std::string>(j, "rollspec:window", "");
  f.detrend = get<std::string>(j, "rollspec:detrend", "");
  f.samples = get<std::size_t>(j, "rollspec:samples", 0);
  f.segments = get<std::size_t>(j, "rollspec:segments", 0);
  f.edof = get<double>(j, "rollspec:equivalent_dof", 0.0);
  f.scale = get<double>(j, "rollspec:scale", 1.0);
  f.source = get<std::string>(j, "rollspec:source", "");
  f.source_hash = get<std::string>(j, "rollspec:source_sha256", "");
  f.version = get<std::string>(j, "rollspec:version", "");
  const auto schema = j.find("tableSchema");
  if (schema != j.end() && schema->is_object() && schema->contains("columns") && (*schema)["columns"].is_array())
    for (const auto& c : (*schema)["columns"]) {
      if (!c.is_object()) continue;
      s.columns.push_back({get<std::string>(c, "titles", ""), get<std::string>(c, "name", ""),
                           get<std::string>(c, "rollspec:channel", ""), get<std::string>(c, "rollspec:signal_unit", ""),
                           get<std::string>(c, "rollspec:signal_unit_origin", "")});
    }
  return s;
}

bool psd_csv_written_by_rollspec(const std::string& csv_path) {
  std::ifstream in(csv_path, std::ios::binary);
  const std::string marker = kMarker;
  std::string head(marker.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (in.gcount() == static_cast<std::streamsize>(head.size()) && head == marker) return true;
  std::string why;
  try {
    return read_psd_sidecar(psd_sidecar_path(csv_path), sha256_file(csv_path), why).has_value();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace rollspec::io
