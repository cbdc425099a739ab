// rollspec.contact.Table: a cached stage table (stiffness, blocked force, equivalent roughness, path
// table) read as the engine reads it before reusing it (stiffness::read_stored_table: file type,
// schema, contact kernel version, data checksum), with its columns as numpy views, its scalars, the
// canonical inputs and input hash the study's stage compares, and the file's provenance.
#include <memory>
#include <optional>

#include "python/bindings.hpp"
#include "src/error.hpp"
#include "src/io/content_hash.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/run/run_phases.hpp"
#include "src/run/study_stiffness_table.hpp"
#include "src/run/study_tables.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/stiffness/stiffness_table.hpp"

namespace rollspec::python {

namespace {

struct Column {
  std::string name;
  const std::vector<double>* values;
  std::vector<py::ssize_t> shape;
};

struct Table {
  std::string kind, path, inputs, input_hash, data_checksum;
  std::string status;  // stiffness_table, tables: "built PATH" or "cached PATH"; read: ""
  double kernel_version = 0.0;
  std::unique_ptr<stiffness::TableData> data;
  std::vector<Column> columns;  // views into *data
  std::vector<std::pair<std::string, double>> scalars;
  py::dict provenance;
};

py::ssize_t size(const std::vector<double>& v) { return static_cast<py::ssize_t>(v.size()); }

// The kind's columns (shapes as the file stores them) and scalars, in the file's names.
void describe(Table& t) {
  using namespace stiffness;
  if (auto* s = dynamic_cast<StiffnessTable*>(t.data.get())) {
    for (auto [n, v] : std::initializer_list<std::pair<const char*, const std::vector<double>*>>{
             {"approach", &s->approach},
             {"force_mean", &s->force_mean},
             {"force_std", &s->force_std},
             {"stiffness_mean", &s->stiffness_mean},
             {"stiffness_std", &s->stiffness_std},
             {"contact_area_mean", &s->contact_area_mean},
             {"plastic_cells_mean", &s->plastic_cells_mean},
             {"max_pressure_mean", &s->max_pressure_mean},
             {"iterations_mean", &s->iterations_mean}})
      t.columns.push_back({n, v, {size(*v)}});
    t.scalars = {{"ball_radius", s->ball_radius},    {"effective_modulus", s->effective_modulus},
                 {"hardness", s->hardness},          {"realisations", static_cast<double>(s->realisations)},
                 {"solver_tolerance", s->tolerance}, {"fit_coefficient", s->fit_coefficient},
                 {"fit_exponent", s->fit_exponent},  {"fit_max_relative_error", s->fit_max_relative_error}};
  } else if (auto* b = dynamic_cast<BlockedForceTable*>(t.data.get())) {
    for (auto [n, v] : std::initializer_list<std::pair<const char*, const std::vector<double>*>>{
             {"position", &b->position},
             {"force", &b->force},
             {"stiffness", &b->stiffness},
             {"psd_wavenumber", &b->psd_wavenumber},
             {"psd", &b->psd}})
      t.columns.push_back({n, v, {size(*v)}});
    if (!b->force_error.empty()) t.columns.push_back({"force_error", &b->force_error, {size(b->force_error)}});
    t.scalars = {{"approach", b->approach}, {"k0", b->k0}, {"mean_force", b->mean_force}, {"load", b->load}};
    if (!b->force_error.empty()) {
      t.scalars.emplace_back("answer_tolerance", b->answer_tolerance);
      t.scalars.emplace_back("load_step", b->load_step);
    }
    if (!b->check_position.empty()) {  // contact BF-9's checks
      t.columns.push_back({"check_position", &b->check_position, {size(b->check_position)}});
      t.columns.push_back({"check_residual", &b->check_residual, {size(b->check_residual)}});
      t.scalars.emplace_back("k0_error", b->k0_error);
    }
  } else if (auto* e = dynamic_cast<EquivalentRoughnessTable*>(t.data.get())) {
    const py::ssize_t strips = static_cast<py::ssize_t>(e->strips), n = size(e->position);
    if (strips * n != size(e->height) || strips * n != size(e->stiffness))
      throw data_error(t.path + ": the equivalent-roughness table's height and stiffness are not strips x positions");
    t.columns = {{"position", &e->position, {n}},
                 {"height", &e->height, {strips, n}},
                 {"psd_wavenumber", &e->psd_wavenumber, {size(e->psd_wavenumber)}},
                 {"psd", &e->psd, {size(e->psd)}},
                 {"stiffness", &e->stiffness, {strips, n}}};
    t.scalars = {{"smooth_approach", e->smooth_approach},
                 {"smooth_stiffness", e->smooth_stiffness},
                 {"load", e->load},
                 {"strips", e->strips}};
  } else if (auto* p = dynamic_cast<PathTableData*>(t.data.get())) {
    const py::ssize_t nj = size(p->approach), nk = size(p->position);
    if (nj * nk != size(p->force)) throw data_error(t.path + ": the path table's force is not approaches x positions");
    t.columns = {{"position", &p->position, {nk}},
                 {"approach", &p->approach, {nj}},
                 {"first_contact", &p->first_contact, {size(p->first_contact)}},
                 {"force", &p->force, {nj, nk}}};
    if (!p->rows.empty()) t.columns.push_back({"rows", &p->rows, {size(p->rows)}});  // B43b: rows per position
    if (!p->check_position.empty()) {                                                // B47's checks
      t.columns.push_back({"check_position", &p->check_position, {size(p->check_position)}});
      t.columns.push_back({"check_approach", &p->check_approach, {size(p->check_approach)}});
    }
    t.scalars = {{"load", p->load}};
  }
}

std::unique_ptr<Table> read(const std::string& path) {
  file_name(path, "path");
  using namespace stiffness;
  struct Known {
    const TableKind* kind;
    const char* name;
    std::unique_ptr<TableData> (*make)();
  };
  const Known known[] = {
      {&kStiffnessTableKind, "stiffness", [] { return std::unique_ptr<TableData>(new StiffnessTable); }},
      {&kBlockedForceTableKind, "blocked_force", [] { return std::unique_ptr<TableData>(new BlockedForceTable); }},
      {&kEquivalentRoughnessTableKind, "equivalent_roughness",
       [] { return std::unique_ptr<TableData>(new EquivalentRoughnessTable); }},
      {&kPathTableKind, "path", [] { return std::unique_ptr<TableData>(new PathTableData); }}};
  auto t = std::make_unique<Table>();
  t->path = path;
  std::string filetype, allowed;
  {
    const io::Hdf5Reader r(path);  // missing: OSError; not HDF5: ValueError
    if (r.has_attribute("/", "filetype")) filetype = r.string_attribute("/", "filetype");
    for (const auto& k : known) allowed += (allowed.empty() ? "" : ", ") + std::string(k.kind->file_type);
    const Known* kind = nullptr;
    for (const auto& k : known)
      if (filetype == k.kind->file_type) kind = &k;
    if (!kind)
      throw data_error(
          path + ": " +
          (filetype.empty() ? "not a rollspec file (no filetype attribute)" : "filetype is '" + filetype + "'") +
          "; allowed: a rollspec table (" + allowed + ")");
    t->kind = kind->name;
    t->data = kind->make();
    for (const char* a : {"filetype", "schema_version", "rollspec_version", "git_sha", "library_versions", "study",
                          "rng", "created", "host", "command_line"})
      if (r.has_attribute("/", a)) t->provenance[a] = r.string_attribute("/", a);
    if (r.has_attribute("/", "seed")) t->provenance["seed"] = static_cast<long long>(r.double_attribute("/", "seed"));
    t->kernel_version = r.double_attribute(kind->kind->group, "kernel_version");
    t->data_checksum = r.string_attribute(kind->kind->group, "data_checksum");
    const StoredIdentity id = read_stored_table(*kind->kind, path, *t->data);  // small: read with the lock held
    t->inputs = id.inputs;
    t->input_hash = id.hash;
  }
  // The hash a study's stage compares is the FNV-1a hash of these inputs: a file whose stored hash is
  // not its inputs' was edited, and no study would reuse it.
  const std::string own = io::hex16(io::fnv1a64(t->inputs));
  if (own != t->input_hash)
    throw data_error(path + ": input_hash " + t->input_hash + " is not the hash of its inputs (" + own +
                     "; damaged or edited file); rebuild with --rebuild");
  t->data->input_hash = t->input_hash;
  describe(*t);
  return t;
}

// The study named by `study_path` with --set `sets`, as the command resolves it.
study::Study study_with(const py::object& study_path, const std::vector<std::string>& sets) {
  run::StudyArgs args;
  args.file = file_name(study_path, "study");
  args.sets = sets;
  return run::resolve_study(args);
}

// `rollspec stiffness STUDY --set ...` in-process: the study's table reused when its input hash and
// data match, built (and written where the command writes it) when missing, refused when it differs.
std::unique_ptr<Table> stiffness_table(const py::object& study_path, const std::vector<std::string>& sets, bool rebuild,
                                       bool quiet, std::optional<int> threads) {
  check_threads(threads, "the table");
  const study::Study s = study_with(study_path, sets);
  run::StudyStiffnessTable answer;
  run_interruptible([&] { answer = run::study_stiffness_table(s, false, rebuild, quiet); }, threads, "");
  auto t = read(answer.path);
  t->status = answer.status;
  return t;
}

// Every table the study's scene shares, as `rollspec run` resolves them before its ensemble.
py::dict tables(const py::object& study_path, const std::vector<std::string>& sets, bool rebuild, bool quiet,
                std::optional<int> threads) {
  check_threads(threads, "a table");
  const study::Study s = study_with(study_path, sets);
  std::vector<run::StudyTable> made;
  run_interruptible([&] { made = run::study_tables(s, false, rebuild, quiet); }, threads, "");
  py::dict out;
  for (const auto& m : made) {
    auto t = read(m.path);
    t->status = m.status;
    out[m.stage.c_str()] = py::cast(t.release(), py::return_value_policy::take_ownership);
  }
  return out;
}

py::array_t<double> view(const Column& c, const py::object& self) {
  std::vector<py::ssize_t> strides(c.shape.size(), sizeof(double));
  if (c.shape.size() == 2) strides[0] = c.shape[1] * static_cast<py::ssize_t>(sizeof(double));
  py::array_t<double> a(c.shape, strides, c.values->data(), self);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

const char* const kTableDoc = R"(A cached stage table as a study run writes it into its tables folder.

kind 'stiffness' (stiffness-HASH.h5: force, stiffness and contact area of a ball pressed onto rough
surfaces against the approach, seed 001 Eq. 11-13), 'blocked_force' (blocked-force-HASH.h5: F0 and k
along the path at the approach d0 carrying the load, and the PSD of F0, D-11), 'equivalent_roughness'
(equivalent-roughness-HASH.h5: h_eq and k_eq per strip and position, ER-1..ER-7) or 'path'
(path-table-HASH.h5: P(delta_j, xi_k), B41-B46). Read with the engine's own checks (file type, schema,
contact kernel version, data checksum) and refused as a study refuses to reuse it, with the same
message. input_hash is the FNV-1a hash of `inputs`, the canonical text of what the table depends on,
which the study compares before reusing the file.

Each column is an attribute (a read-only numpy array, SI units as in the file: m, N, N/m, m^2, Pa,
rad/m, m^3 or N^2 m); each scalar too (a float). columns and scalars list them.
)";

// The parameters stiffness_table and tables share, in their docstrings.
const char* const kStudyTableParameters = R"(Parameters
----------
study : str or os.PathLike
    The study file.
set : list of str
    Overrides 'section.key=value', as --set.
rebuild : bool
    Replace a table whose inputs differ or that is damaged (--rebuild).
quiet : bool
    No progress lines on stderr (--quiet).
threads : int or None
    OpenMP threads of the builds (None: OMP_NUM_THREADS, else every core); a table does not depend on it.
)";

const std::string kStiffnessTableDoc =
    R"(The stiffness table of a study, as `rollspec stiffness STUDY --set ...` makes it.

The study's [stiffness] table (auto: <table_dir>/stiffness-<input hash>.h5 beside the study) is reused
when its input hash, inputs and data checksum match, built and written there when missing (the
elastic-plastic half-space solve of every rough-surface realisation, OpenMP threads, the same bits
for any thread count, the interpreter lock released), and refused with the command's message when
its inputs differ or it is damaged, unless rebuild. A `stiffness` or `ball-on-beam` study.

)" + std::string(kStudyTableParameters) +
    R"(
Returns
-------
Table
    kind 'stiffness', read back from the file; status says 'built PATH' or 'cached PATH'.
)";

const std::string kTablesDoc =
    R"(Every table a study's scene shares, reused or built as `rollspec run STUDY` does before its ensemble.

The stiffness table ([contact] law = table), the blocked-force table ([contact] blocked_force = solver),
the equivalent-roughness table ([contact] filter = solver) and the path table ([contact] law = path),
whichever the study uses: each reused when its input hash, inputs and data checksum match, built and
written where the run writes it (<table_dir>/KIND-<input hash>.h5) when missing, and refused with the
run's message when its inputs differ or it is damaged, unless rebuild. No realisation runs and no
result is written; a run of the same study then finds every table cached. The same bits for any thread
count; the interpreter lock is released while tables are built.

)" + std::string(kStudyTableParameters) +
    R"(
Returns
-------
dict
    {stage: Table} in the run's order, the stage as `rollspec plan` names it (stiffness_table,
    blocked_force, equivalent_roughness, path_table); each Table read back from its file, its status
    'built PATH' or 'cached PATH'. Empty for a study that shares no table.
)";

}  // namespace

void bind_tables(py::module_& m) {
  using py::arg;
  py::class_<Table> c(m, "Table", kTableDoc);
  c.def_static("read", &read,
               "The table file `path` (str): a rollspec stiffness, blocked-force, equivalent-roughness or path table. "
               "ValueError for a damaged, edited, foreign or other kernel version's file (the command's message), "
               "OSError for a missing one.",
               arg("path"));
  c.def_property_readonly(
      "status", [](const Table& t) { return t.status; },
      "stiffness_table and tables: 'built PATH' or 'cached PATH', as `rollspec stiffness` prints it; read: ''.");
  c.def_property_readonly(
      "kind", [](const Table& t) { return t.kind; }, "'stiffness', 'blocked_force', 'equivalent_roughness' or 'path'.");
  c.def_property_readonly(
      "path", [](const Table& t) { return t.path; }, "The file read.");
  c.def_property_readonly(
      "input_hash", [](const Table& t) { return t.input_hash; },
      "16 hex digits: FNV-1a of `inputs`, the name part of an automatic table file.");
  c.def_property_readonly(
      "inputs", [](const Table& t) { return t.inputs; },
      "The canonical text of the table's inputs (contact kernel version, keys, grid, PSD files' fingerprint).");
  c.def_property_readonly(
      "data_checksum", [](const Table& t) { return t.data_checksum; },
      "16 hex digits over the columns' bytes, checked on reading.");
  c.def_property_readonly(
      "kernel_version", [](const Table& t) { return t.kernel_version; }, "The contact kernel version that built it.");
  c.def_property_readonly(
      "provenance", [](const Table& t) { return t.provenance; },
      "The file's provenance: filetype, schema_version, rollspec_version, git_sha, study (the canonical text of "
      "the study that built it), seed, rng, created, host, command_line, library_versions.");
  c.def_property_readonly(
      "columns",
      [](const py::object& self) {
        py::dict d;
        for (const auto& col : self.cast<const Table&>().columns) d[col.name.c_str()] = view(col, self);
        return d;
      },
      "Every column by name (read-only numpy views of the table, not copies).");
  c.def_property_readonly(
      "scalars",
      [](const Table& t) {
        py::dict d;
        for (const auto& [n, v] : t.scalars) d[n.c_str()] = v;
        return d;
      },
      "Every scalar attribute by name (SI units).");
  c.def("__getattr__", [](const py::object& self, const std::string& name) -> py::object {
    const Table& t = self.cast<const Table&>();
    for (const auto& col : t.columns)
      if (col.name == name) return view(col, self);
    for (const auto& [n, v] : t.scalars)
      if (n == name) return py::float_(v);
    throw py::attribute_error("a " + t.kind + " table has no column or scalar '" + name + "'");
  });
  m.def("stiffness_table", &stiffness_table, kStiffnessTableDoc.c_str(), arg("study"), py::kw_only(),
        arg("set") = std::vector<std::string>{}, arg("rebuild") = false, arg("quiet") = true,
        arg("threads") = py::none());
  m.def("tables", &tables, kTablesDoc.c_str(), arg("study"), py::kw_only(), arg("set") = std::vector<std::string>{},
        arg("rebuild") = false, arg("quiet") = true, arg("threads") = py::none());
  c.def("__repr__", [](const Table& t) {
    return "<rollspec.contact.Table " + t.kind + " " + t.input_hash + " from " + t.path + ">";
  });
}

}  // namespace rollspec::python
