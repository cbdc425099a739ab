#include "src/stiffness/cached_table.hpp"

#include <filesystem>
#include <map>
#include <sstream>

#include "kernels/contact/version.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/provenance.hpp"
#include "src/io/references.hpp"
#include "src/stiffness/table_location.hpp"
#include "src/stiffness/table_text.hpp"

namespace fs = std::filesystem;

namespace rollspec::stiffness {

namespace {

constexpr const char* kSchemaVersion = "1.0";
constexpr int kSchemaMajor = 1;

std::map<std::string, std::string> parse_lines(const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line, section;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') section = line;
    const auto eq = line.find(" = ");
    if (eq != std::string::npos) out[section + " " + line.substr(0, eq)] = line.substr(eq + 3);
  }
  return out;
}

// The keys whose values differ between a stored table's inputs and the study's, one per line.
std::string differences(const std::string& stored, const std::string& wanted) {
  const auto a = parse_lines(stored), b = parse_lines(wanted);
  std::string out;
  for (const auto& [k, v] : b) {
    const auto it = a.find(k);
    if (it == a.end())
      out += "\n  " + k + ": not in the table, study has " + v;
    else if (it->second != v)
      out += "\n  " + k + ": table has " + it->second + ", study has " + v;
  }
  for (const auto& [k, v] : a)
    if (!b.count(k)) out += "\n  " + k + ": table has " + v + ", the study does not";
  return out.empty() ? " (no key differs; the stored hash is inconsistent)" : out;
}

}  // namespace

StoredIdentity read_stored_table(const TableKind& kind, const std::string& path, TableData& t) {
  const io::Hdf5Reader r(path);
  io::check_filetype(r, kind.file_type, kSchemaMajor);
  const double kv = r.double_attribute(kind.group, "kernel_version");
  if (static_cast<int>(kv) != contact::kernel_version)
    throw data_error(path + ": built by contact kernel version " + io::exact_text(kv) + ", this rollspec has version " +
                     std::to_string(contact::kernel_version) + "; rebuild with --rebuild");
  t.load_from(r);
  if (r.string_attribute(kind.group, "data_checksum") != t.checksum())
    throw data_error(path + ": the " + kind.title +
                     "'s data do not match its checksum (damaged or edited file); rebuild with --rebuild");
  return {r.string_attribute(kind.group, "inputs"), r.string_attribute(kind.group, "input_hash")};
}

CachedTable::CachedTable(const TableKind& kind, const TableStore& store, std::string inputs,
                         const std::string& explicit_path)
    : kind_(kind), store_(store), inputs_(std::move(inputs)), hash_(io::hex16(io::fnv1a64(inputs_))) {
  const fs::path dir = fs::path(store_.study_file).parent_path();
  automatic_ = explicit_path.empty();
  if (!automatic_)
    path_ = (fs::path(explicit_path).is_absolute() ? fs::path(explicit_path) : dir / explicit_path).string();
  else
    path_ = (dir / store_.table_dir / (kind.file_prefix + hash_ + ".h5")).string();
}

TableState CachedTable::inspect(TableData& scratch, std::string& why) const {
  if (!fs::exists(path_)) return TableState::missing;
  try {
    const StoredIdentity stored = read_stored_table(kind_, path_, scratch);
    if (stored.hash != hash_) {
      why = path_ + ": table inputs differ from the study's (hash " + stored.hash + " vs " + hash_ +
            "):" + differences(stored.inputs, inputs_);
      return TableState::mismatched;
    }
    if (stored.inputs != inputs_) {
      why = path_ + ": table hash matches but its inputs differ:" + differences(stored.inputs, inputs_);
      return TableState::mismatched;
    }
    return TableState::valid;
  } catch (const UserError& e) {
    why = e.what();
    return TableState::mismatched;
  }
}

void CachedTable::resolve(TableData& t, bool rebuild, const std::function<void(TableData&)>& build,
                          std::string& status) const {
  std::string why;
  const TableState state = inspect(t, why);
  if (state == TableState::valid && !rebuild) {
    status = "cached " + path_;
    t.input_hash = hash_;
    return;
  }
  if (state == TableState::mismatched && !rebuild) throw data_error(why + "\nrun with --rebuild to replace it");
  // Before the build: never replace anything but a rollspec table.
  const std::string write_path = table_write_path(store_, path_, kind_.file_type, automatic_);
  build(t);
  t.input_hash = hash_;
  if (ensemble::mpi_rank() == 0) write(write_path, t);
  ensemble::mpi_barrier();  // the table file exists for every rank from here on
  status = "built " + path_;
}

void CachedTable::write(const std::string& write_path, const TableData& t) const {
  io::Hdf5Writer w(write_path);
  io::write_provenance(w, kind_.file_type, kSchemaVersion, store_.study_text, store_.seed);
  io::write_references(w, kind_.references);
  t.save_to(w);
  w.attribute(kind_.group, "schema_version", std::string(kSchemaVersion));
  w.attribute(kind_.group, "kernel_version", static_cast<double>(contact::kernel_version));
  w.attribute(kind_.group, "inputs", inputs_);
  w.attribute(kind_.group, "input_hash", hash_);
  w.attribute(kind_.group, "data_checksum", t.checksum());
  w.commit();
}

std::string table_plan_reason(const CachedTable& t, TableState state, const std::string& why) {
  switch (state) {
    case TableState::valid:
      return t.path() + " (input hash " + t.hash() + ")";
    case TableState::missing:
      return "no " + std::string(t.kind().title) + " with input hash " + t.hash() + " at " + t.path();
    case TableState::mismatched:
      break;
  }
  return "REFUSED unless --rebuild: " + why;
}

}  // namespace rollspec::stiffness
