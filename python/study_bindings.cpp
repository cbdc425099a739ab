// rollspec.studies: a study run in-process through the engine's own run (src/run/run_phases.hpp's
// run_request, what `rollspec run` calls after reading its options), so the result file holds the
// command's bits. The run goes on in a worker thread with the interpreter lock released; the calling
// thread checks Python's signals, and a Ctrl-C stops the ensemble between realisations as the
// command's SIGINT does: completed chunks stay checkpointed beside the result and resume=True
// finishes them. A study comes from a file, or from text or a dict (Study), read by the engine's own
// loader as if it were a file of that name; plan() is `rollspec plan`'s data (src/run/study_plan.hpp).
#include <omp.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <cmath>
#include <chrono>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "python/bindings.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/run/run_phases.hpp"
#include "src/run/study_plan.hpp"
#include "src/run/sweep_run.hpp"

namespace rollspec::python {

namespace {

// The engine's exit code of a run stopped by a signal (or by request_stop).
bool interrupted(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const UserError& u) {
    return u.exit_code() == kExitInterrupted;
  } catch (...) {
    return false;
  }
}

// A study as the engine reads it: a file, or text named by a path (messages, relative paths and the
// default result name are the path's) or by "<string>" / "<dict>" (no default result name).
struct Study {
  run::StudyArgs args;
  bool named = true;
};

// A value of a dict study or of a set dict as the study's text writes it: true/false, an integer, the
// shortest text of a float that reads back as the same double, a string, or a list "a, b, c".
std::string value_text(const py::handle& v, const std::string& key) {
  // numpy scalars by their kind: bool, integer or float
  const std::string kind = py::hasattr(v, "dtype") ? py::str(v.attr("dtype").attr("kind")).cast<std::string>() : "";
  if (py::isinstance<py::bool_>(v) || kind == "b") return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(v) || kind == "i" || kind == "u") {
    const auto integer = py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()));
    if (!integer) throw py::error_already_set();
    return py::str(integer).cast<std::string>();
  }
  if (py::isinstance<py::float_>(v) || kind == "f") return py::repr(py::float_(v.cast<double>())).cast<std::string>();
  if (py::isinstance<py::str>(v)) {
    const auto text = v.cast<std::string>();
    if (text.find_first_of("\n\r") != std::string::npos)
      refuse(key, py::repr(v).cast<std::string>(), "holds a line break", "a one-line value");
    return text;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::string out;
    for (const auto& x : v) out += (out.empty() ? "" : ", ") + value_text(x, key);
    return out;
  }
  refuse(key, py::repr(v).cast<std::string>(), "is a " + py::type::of(v).attr("__name__").cast<std::string>(),
         "a bool, int, float, str or a list of them");
}

// The command's --set texts: ["section.key=value", ...], or a dict {"section.key": value}.
std::vector<std::string> set_texts(const py::handle& sets) {
  std::vector<std::string> out;
  if (py::isinstance<py::dict>(sets)) {
    for (const auto& [k, v] : sets.cast<py::dict>()) {
      const auto key = py::str(k).cast<std::string>();
      out.push_back(key + "=" + value_text(v, "set " + key));
    }
    return out;
  }
  if (py::isinstance<py::str>(sets))
    refuse("set", py::repr(sets).cast<std::string>(), "is one string",
           "a list [\"section.key=value\", ...] or a dict {\"section.key\": value}");
  const std::string allowed = "a list [\"section.key=value\", ...] or a dict {\"section.key\": value}";
  if (!py::isinstance<py::iterable>(sets))
    throw py::type_error("set: " + py::repr(sets).cast<std::string>() + " of type " +
                         py::type::of(sets).attr("__name__").cast<std::string>() + "; allowed: " + allowed);
  for (const auto& x : sets) {
    if (!py::isinstance<py::str>(x))
      throw py::type_error("set: an item " + py::repr(x).cast<std::string>() + "; allowed: " + allowed);
    out.push_back(x.cast<std::string>());
  }
  return out;
}

// Refuses what the engine would refuse of the study, with its one line, before anything runs.
void check_study(const run::StudyArgs& args) {
  py::gil_scoped_release release;  // a sweep's every point is checked (values, shapes, memory)
  if (!run::load_sweep(args, {}, {run::kDefaultMaxSweepPoints, true, false})) run::resolve_study(args);
}

Study study_from_text(const std::string& text, const std::optional<std::filesystem::path>& path,
                      const char* anonymous) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    refuse("text", "''", "is empty", "a study's INI text: [study] scene = ... and the scene's sections");
  Study s{{path ? path->string() : std::string(anonymous), {}, text}, path.has_value()};
  check_study(s.args);
  return s;
}

Study study_from_dict(const py::dict& sections, const std::optional<std::filesystem::path>& path) {
  std::string text;
  for (const auto& [name, keys] : sections) {
    const auto section = py::str(name).cast<std::string>();
    if (!py::isinstance<py::dict>(keys))
      refuse(section, py::repr(keys).cast<std::string>(), "is not a dict", "{\"section\": {\"key\": value}}");
    text += (text.empty() ? "[" : "\n[") + section + "]\n";
    for (const auto& [k, v] : keys.cast<py::dict>()) {
      const auto key = py::str(k).cast<std::string>();
      text += key + " = " + value_text(v, section + "." + key) + "\n";
    }
  }
  return study_from_text(text, path, "<dict>");
}

Study study_of(const py::handle& study) {
  if (py::isinstance<Study>(study)) return study.cast<Study>();
  if (!py::isinstance<py::str>(study) && !py::hasattr(study, "__fspath__"))
    throw py::type_error("study: " + py::repr(study).cast<std::string>() +
                         "; allowed: a study file's path, or a rollspec.studies.Study (from_text, from_dict)");
  return Study{{file_name(study, "study"), {}, {}}, true};
}

}  // namespace

void run_interruptible(const std::function<void()>& work, std::optional<int> threads, const std::string& hint) {
  ensemble::clear_stop();
  std::exception_ptr error;
  std::atomic<bool> done{false};
  bool stopped = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        if (threads) omp_set_num_threads(*threads);
        work();
      } catch (...) {
        error = std::current_exception();
      }
      done = true;
    });
    while (!done) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      py::gil_scoped_acquire hold;
      if (!stopped && PyErr_CheckSignals() != 0) {  // Ctrl-C (KeyboardInterrupt) or another handler raised
        stopped = true;
        ensemble::request_stop();
      }
    }
    worker.join();
  }
  if (stopped) {
    ensemble::clear_stop();
    if (error && interrupted(error)) {  // the engine's own line: what it kept and how to go on
      PyErr_Clear();
      try {
        std::rethrow_exception(error);
      } catch (const UserError& u) {
        PyErr_SetString(PyExc_KeyboardInterrupt, (std::string(u.what()) + hint).c_str());
      }
    }
    throw py::error_already_set();  // the handler's exception (KeyboardInterrupt), or the one set above
  }
  if (error) std::rethrow_exception(error);
}

namespace {

std::string run_study(const py::object& study_arg, const std::optional<std::filesystem::path>& out,
                      const py::object& set_arg, bool resume, bool restart, bool force, bool rebuild, bool quiet,
                      std::optional<int> threads) {
  check_threads(threads, "the result");
  const Study study = study_of(study_arg);
  if (!out && !study.named)
    refuse("out", "None", "a study from text or a dict has no file name to name its result by",
           "the result file's path (or the study's path=)");
  run::RunRequest q;
  q.study = study.args;
  for (auto& s : set_texts(set_arg)) q.study.sets.push_back(std::move(s));
  q.out = out ? out->string() : std::string();
  q.resume = resume, q.restart = restart, q.force = force, q.rebuild = rebuild, q.quiet = quiet;
  // The command's default: the study's name with .h5, in the current directory (resolve_run).
  const std::string written = q.out.empty() ? std::filesystem::path(q.study.file).stem().string() + ".h5" : q.out;

  run_interruptible([&] { run::run_request(q); }, threads, " (in Python: resume=True)");
  return written;
}

py::dict plan_study(const py::object& study_arg, const py::object& set_arg, bool probe) {
  run::StudyArgs args = study_of(study_arg).args;
  for (auto& s : set_texts(set_arg)) args.sets.push_back(std::move(s));
  if (run::load_sweep(args, {}, {run::kDefaultMaxSweepPoints, true, false}))
    refuse("study", args.file, "has a [sweep]", "a study of one point (plan each point with its --set)");
  run::StudyPlan p;
  {
    py::gil_scoped_release release;  // a probe runs realisation 0 and times table solves
    p = run::plan_study(args, probe);
  }
  py::dict d;
  d["study"] = args.file, d["scene"] = p.scene, d["realisations"] = p.realisations, d["seed"] = p.seed;
  d["threads"] = p.threads;
  d["memory_bytes"] = p.memory.bytes, d["memory_largest"] = p.memory.what, d["memory_keys"] = p.memory.keys;
  py::list terms;
  for (const auto& [what, bytes] : p.memory.terms)
    terms.append(py::dict(py::arg("what") = what, py::arg("bytes") = bytes));
  d["memory_terms"] = terms;
  d["available_bytes"] = p.available_bytes, d["over_memory"] = p.over_memory;
  d["checkpoint_chunks"] = p.chunks, d["checkpoint_chunk_bytes"] = p.chunk_bytes;
  d["warnings"] = p.warnings, d["note"] = p.note;
  py::list stages;
  for (const auto& s : p.stages)
    stages.append(py::dict(py::arg("stage") = s.stage, py::arg("status") = scenes::status_name(s.status),
                           py::arg("reason") = s.reason, py::arg("table") = s.table));
  d["stages"] = stages;
  py::list tables;
  for (const auto& t : p.tables)
    tables.append(py::dict(py::arg("table") = t.table, py::arg("cpu_seconds") = t.seconds,
                           py::arg("wall_seconds") = t.seconds / t.threads, py::arg("threads") = t.threads,
                           py::arg("probe") = t.how));
  d["tables"] = tables;
  d["jackknife"] = p.jackknife ? py::object(py::dict(py::arg("table") = p.jk.table, py::arg("sub_tables") = p.jk.n,
                                                     py::arg("unit") = p.jk.unit, py::arg("ensembles") = p.jk.n + 1))
                               : py::object(py::none());
  d["seconds_per_realisation"] =
      p.seconds_per_realisation ? py::object(py::float_(*p.seconds_per_realisation)) : py::object(py::none());
  d["ensemble_seconds"] =
      p.seconds_per_realisation ? py::object(py::float_(p.ensemble_seconds())) : py::object(py::none());
  d["not_probed"] = p.not_probed.empty() ? py::object(py::none()) : py::object(py::str(p.not_probed));
  return d;
}

}  // namespace

void bind_studies(py::module_& m) {
  py::class_<Study>(m, "Study",
                    R"(A study: a file, or INI text, or a dict of sections, read and checked by the engine's own
loader (the command's one-line messages as ValueError, naming the file or "<string>"/"<dict>", the line
and the key). rollspec.studies.run and plan take a Study wherever they take a study file's path.)")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path) {
            Study s{{path.string(), {}, {}}, true};
            check_study(s.args);
            return s;
          },
          py::arg("path"),
          "The study file `path` (INI), checked as `rollspec plan` checks it; OSError when it is missing.")
      .def_static(
          "from_text",
          [](const std::string& text, const std::optional<std::filesystem::path>& path) {
            return study_from_text(text, path, "<string>");
          },
          py::arg("text"), py::arg("path") = py::none(),
          R"(A study from its INI text ("[study]\nscene = ...\n..."), read as if it were the file `path`: messages
name it (else "<string>" and the line), relative paths (profiles, tables) resolve from its directory (else
the current directory), and run() names its result after it (else run() needs out=).)")
      .def_static("from_dict", &study_from_dict, py::arg("sections"), py::arg("path") = py::none(),
                  R"(A study from {"section": {"key": value}}: written as INI text in the dict's order (bool as
true/false, a float as the shortest text that reads back as the same double, a list as "a, b, c"), then
read as from_text reads it (messages name "<dict>" and the line of that text: see .text). Values carry the
study keys' units (SI: Hz, s, m, kg, N; `rollspec keys` lists them).)")
      .def_property_readonly(
          "path", [](const Study& s) { return s.named ? py::object(py::str(s.args.file)) : py::object(py::none()); },
          "The file the study is (or is read as), or None for text or a dict without a path.")
      .def_property_readonly(
          "text",
          [](const Study& s) {
            return s.args.text.empty() ? py::object(py::none()) : py::object(py::str(s.args.text));
          },
          "The study's INI text (None for a study read from its file at each run).")
      .def("__repr__", [](const Study& s) {
        return std::string("rollspec.studies.Study(") + (s.args.text.empty() ? "file " : "text ") + s.args.file + ")";
      });
  m.def("run", &run_study, py::arg("study"), py::arg("out") = py::none(), py::kw_only(), py::arg("set") = py::list(),
        py::arg("resume") = false, py::arg("restart") = false, py::arg("force") = false, py::arg("rebuild") = false,
        py::arg("quiet") = true, py::arg("threads") = py::none(),
        R"(Runs the study (a study file's path, or a Study from text or a dict) in this process, as `rollspec
run STUDY --out OUT --set ...` does, and returns the path of the result file written (out, or the study's
name with .h5 in the current directory; a study without a path needs out). The result holds the
command's bits, for any thread count: rollspec.studies.open(path) reads it as xarray.

set      ["section.key=value", ...] or {"section.key": value}: the command's --set overrides
resume   finish the checkpoint an interrupted run left beside `out`; restart: discard it
force    replace an `out` that is not a rollspec result, and run past the memory estimate
rebuild  rebuild cached tables whose inputs differ instead of refusing them
quiet    no progress lines on stderr (False: the command's)
threads  OpenMP threads of the ensemble (None: OMP_NUM_THREADS, else every core)

The interpreter lock is released while the study runs. Ctrl-C stops the ensemble between
realisations and raises KeyboardInterrupt: completed chunks are kept in OUT.checkpoint and
run(..., resume=True) finishes them with the same bits; a table being built finishes first.
Errors are the command's one line: ValueError (bad study or data), OSError (a file missing or not
writable).)");
  m.def("plan", &plan_study, py::arg("study"), py::kw_only(), py::arg("set") = py::list(), py::arg("probe") = false,
        R"(What `rollspec plan STUDY --set ... [--probe]` prints, as a dict (nothing is computed but the probe's
solves, no file is written):

study, scene, realisations, seed   the study's [study] keys (study: its path, or "<string>"/"<dict>")
threads                  the ensemble's OpenMP threads the estimates assume
memory_bytes             estimated peak resident memory (bytes); memory_largest, memory_keys: its largest
                         term and the keys that drive it; memory_terms: [{"what", "bytes"}]
available_bytes          memory available now (bytes); over_memory: run refuses the study (unless forced),
                         and the entries below stay empty
checkpoint_chunks, checkpoint_chunk_bytes   the checkpoint beside the result while an ensemble runs (bytes)
warnings, note           the scene's warnings; what measured profiles resolve ("" if none)
stages                   [{"stage", "status": "run"|"cached"|"skipped", "reason", "table": bool}], in
                         pipeline order
tables                   missing tables timed on a few solves: [{"table", "cpu_seconds", "wall_seconds" (s),
                         "threads", "probe"}]
jackknife                None, or {"table", "sub_tables", "unit", "ensembles"}: [stiffness] table_error's runs
seconds_per_realisation  probe=True: the time of realisation 0 (s), and ensemble_seconds the ensemble's
                         estimate on `threads` (s); None otherwise, not_probed says why when probed

The interpreter lock is released while it plans. A study with a [sweep] is refused (plan each point).)");
}

}  // namespace rollspec::python
