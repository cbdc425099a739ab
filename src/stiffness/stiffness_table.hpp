#pragma once
// Contact stiffness tables (design §4; seed 001 §3.2-3.3, Eq. 11-13): the force P(delta), stiffness
// k(delta) = dP/d delta (frozen-set solve) and real contact area of a smooth ball pressed onto
// rough-surface realisations by the elastic-plastic half-space solver, mean and standard deviation
// over realisations. delta is the approach from first contact (the highest summit under the ball;
// for a smooth flat, from the touching position);
// the roughness the ball rolls over enters the dynamics separately through the line texture (D-1).
//
// A table records every input it depends on as canonical text and its FNV-1a hash (`input_hash`);
// a stored table is reused only when the hash, the schema and the contact kernel version match,
// and a checksum over its data detects truncated or altered files.
#include <cstdint>
#include <string>
#include <vector>

namespace rollspec::study {
class Study;
}

namespace rollspec::stiffness {

constexpr const char* kTableFileType = "rollspec-stiffness-table";
constexpr const char* kTableSchemaVersion = "1.0";
constexpr int kTableSchemaMajor = 1;

struct StiffnessTable {
  std::vector<double> approach;          // delta_j, m (first entry 0)
  std::vector<double> force_mean, force_std;
  std::vector<double> stiffness_mean, stiffness_std;
  std::vector<double> contact_area_mean, plastic_cells_mean, max_pressure_mean, iterations_mean;
  double ball_radius = 0.0, effective_modulus = 0.0, hardness = 0.0;  // m, Pa, Pa (inf: elastic)
  std::int64_t realisations = 0;
  double tolerance = 0.0;                // solver stopping rule (complementarity error)
  double fit_coefficient = 0.0, fit_exponent = 0.0, fit_max_relative_error = 0.0;  // P = c delta^n
  std::string inputs;                    // canonical input text
  std::string input_hash;                // 16 hex digits of FNV-1a over `inputs`
  // Approach and stiffness where the mean force equals `load` (monotone interpolation of the table).
  double approach_at(double load) const;
  double stiffness_at(double load) const;
};

// The [stiffness] keys (and nothing else: surfaces and PSD keys come from texture_keys.hpp).
struct TableSpec {
  std::string inputs;  // canonical text of every input
  std::string hash;
};

// What a study asks for: canonical inputs and their hash (no computation).
TableSpec table_spec(const study::Study& s, double ball_radius, double effective_modulus);
// Where a study's table lives: [stiffness] table, or <table_dir>/stiffness-<hash>.h5.
std::string table_path(const study::Study& s, const TableSpec& spec);

enum class TableState { missing, valid, mismatched };
// Checks a stored table without using its data: missing, valid (hash, schema, kernel version and
// checksum match) or mismatched; `why` names the differing inputs or the damage.
TableState inspect_table(const std::string& path, const TableSpec& spec, std::string& why);

// Builds the table (OpenMP over surface realisations). Throws UserError (exit 65) naming the
// realisation and step if a contact solve does not converge.
StiffnessTable build_table(const study::Study& s, double ball_radius, double effective_modulus, const TableSpec& spec,
                           bool quiet);

void write_table(const std::string& path, const StiffnessTable& t, const std::string& study_text, std::uint64_t seed);
StiffnessTable read_table(const std::string& path);  // checks filetype, schema, kernel version, checksum

// The stage as scenes use it: reuse a valid table, build a missing one, refuse a mismatched or
// damaged one (exit 65, naming the differences) unless `rebuild`. `status` says which.
StiffnessTable resolve_table(const study::Study& s, double ball_radius, double effective_modulus, bool rebuild,
                             bool quiet, std::string& status);

}  // namespace rollspec::stiffness
