#pragma once
// One cached stage table (stiffness tables, blocked-force tables, and any later table stage): its
// canonical inputs and their FNV-1a hash, where it lives, whether a stored file may be reused
// (file type, schema, contact kernel version, inputs and data checksum all match), what differs
// from the study when it may not, and how it is built, written (provenance, identity attributes,
// temp file renamed) and read back. The table's own data come and go through TableData.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "src/study/sections/key_origin.hpp"

namespace rollspec::io {
class Hdf5Reader;
class Hdf5Writer;
}  // namespace rollspec::io

namespace rollspec::stiffness {

// What one kind of table stores besides its identity: datasets and attributes under its group,
// and the checksum over them that detects a truncated or edited file.
class TableData {
 public:
  virtual ~TableData() = default;
  virtual void load_from(const io::Hdf5Reader& r) = 0;
  virtual void save_to(io::Hdf5Writer& w) const = 0;
  virtual std::string checksum() const = 0;
  std::string input_hash;  // of the CachedTable that resolved it (set by CachedTable::resolve)
};

struct TableKind {
  const char* file_type;    // provenance file type, e.g. "rollspec-stiffness-table"
  const char* group;        // group holding the identity attributes, e.g. "/stiffness"
  const char* file_prefix;  // automatic file name <table_dir>/<prefix><hash>.h5
  const char* title;        // in messages, e.g. "stiffness table"
  // The papers and theory-note equations its build uses (io/references.hpp ids), in /provenance/references.
  std::vector<std::string> references;
};

enum class TableState { missing, valid, mismatched };

// Where a study's tables live and what their files record of it (table_location.hpp says what
// may be written).
struct TableStore {
  std::string study_file;  // its directory resolves relative table paths
  std::string table_dir;   // [stiffness] table_dir as written
  study::KeyOrigin table_origin, table_dir_origin;
  std::vector<std::string> inputs;  // files the study reads: a table never replaces one
  std::string study_text;           // the study's canonical text, for the provenance
  std::uint64_t seed = 0;
};

class CachedTable {
 public:
  CachedTable() = default;
  // `explicit_path` (relative to the study's directory) or "" for the automatic name in
  // [stiffness] table_dir.
  CachedTable(const TableKind& kind, const TableStore& store, std::string inputs,
              const std::string& explicit_path = "");

  const std::string& inputs() const { return inputs_; }
  const std::string& hash() const { return hash_; }
  const std::string& path() const { return path_; }
  const TableKind& kind() const { return kind_; }

  // Without building anything: missing, valid, or mismatched (`why` names the differing inputs or
  // the damage). `scratch` receives the stored data while they are checked.
  TableState inspect(TableData& scratch, std::string& why) const;
  // Reuses a valid table, builds a missing one with `build`, refuses a mismatched or damaged one
  // (exit 65, naming the differences) unless `rebuild`. Collective under MPI: every rank builds or
  // reads, rank 0 writes. `status` says "cached <path>" or "built <path>".
  void resolve(TableData& t, bool rebuild, const std::function<void(TableData&)>& build, std::string& status) const;

 private:
  void write(const std::string& write_path, const TableData& t) const;
  TableKind kind_{};
  TableStore store_;
  std::string inputs_, hash_, path_;
  bool automatic_ = true;
};

// What a stored table's file records of its inputs: their canonical text and its hash.
struct StoredIdentity {
  std::string inputs, hash;
};
// Opens a stored table of `kind`, checks its file type, schema, contact kernel version and data
// checksum, and loads its data into t (not t.input_hash). Throws data_error naming what is wrong.
StoredIdentity read_stored_table(const TableKind& kind, const std::string& path, TableData& t);

// The plan line of a table stage in `state`: cached, or run and why (missing; refused unless --rebuild).
std::string table_plan_reason(const CachedTable& t, TableState state, const std::string& why);

}  // namespace rollspec::stiffness
