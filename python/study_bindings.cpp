// rollspec.studies: a study run in-process through the engine's own run (src/run/run_phases.hpp's
// run_request, what `rollspec run` calls after reading its options), so the result file holds the
// command's bits. The run goes on in a worker thread with the interpreter lock released; the calling
// thread checks Python's signals, and a Ctrl-C stops the ensemble between realisations as the
// command's SIGINT does: completed chunks stay checkpointed beside the result and resume=True
// finishes them.
#include <omp.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
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

std::string run_study(const std::filesystem::path& study, const std::optional<std::filesystem::path>& out,
                      const std::vector<std::string>& sets, bool resume, bool restart, bool force, bool rebuild,
                      bool quiet, std::optional<int> threads) {
  if (threads && *threads < 1)
    refuse("threads", std::to_string(*threads), "fewer than one",
           "a thread count >= 1 (None: OMP_NUM_THREADS, else every core); the result does not depend on it");
  run::RunRequest q;
  q.study.file = study.string();
  q.study.sets = sets;
  q.out = out ? out->string() : std::string();
  q.resume = resume, q.restart = restart, q.force = force, q.rebuild = rebuild, q.quiet = quiet;
  // The command's default: the study's name with .h5, in the current directory (resolve_run).
  const std::string written = q.out.empty() ? study.stem().string() + ".h5" : q.out;

  ensemble::clear_stop();
  std::exception_ptr error;
  std::atomic<bool> done{false};
  bool stopped = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        if (threads) omp_set_num_threads(*threads);
        run::run_request(q);
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
        PyErr_SetString(PyExc_KeyboardInterrupt, (std::string(u.what()) + " (in Python: resume=True)").c_str());
      }
    }
    throw py::error_already_set();  // the handler's exception (KeyboardInterrupt), or the one set above
  }
  if (error) std::rethrow_exception(error);
  return written;
}

}  // namespace

void bind_studies(py::module_& m) {
  m.def("run", &run_study, py::arg("study"), py::arg("out") = py::none(), py::kw_only(),
        py::arg("set") = std::vector<std::string>{}, py::arg("resume") = false, py::arg("restart") = false,
        py::arg("force") = false, py::arg("rebuild") = false, py::arg("quiet") = true, py::arg("threads") = py::none(),
        R"(Runs the study file `study` in this process, as `rollspec run STUDY --out OUT --set ...` does, and
returns the path of the result file written (out, or the study's name with .h5 in the current
directory). The result holds the command's bits, for any thread count.

set      ["section.key=value", ...]: the command's --set overrides
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
}

}  // namespace rollspec::python
