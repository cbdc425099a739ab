#include "src/run/sweep_run.hpp"

#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/hdf5_stack.hpp"
#include "src/io/input_file.hpp"
#include "src/io/output_target.hpp"
#include "src/io/number_text.hpp"
#include "src/io/provenance.hpp"
#include "src/io/temp_files.hpp"
#include "src/text_trim.hpp"

namespace rollspec::run {

namespace fs = std::filesystem;

namespace {

// The study file's text, or nullopt for a file larger than any study: the loader refuses that one
// with its own message, before reading it.
std::optional<std::string> read_text(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw missing_input("cannot read study file '" + path + "': it is a directory; expected an INI file");
  io::require_regular_input(path, "study file");
  constexpr std::uintmax_t kLargestStudy = 4u << 20;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec || bytes > kLargestStudy) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw missing_input("cannot open study file '" + path + "'");
  std::ostringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

study::Study point_study(const StudyArgs& a) { return study::Study::parse(a.file, a.text, a.sets, scenes::schema_for); }

// Every value of every swept key, loaded alone into the study: a bad value is refused before any work,
// and so is a value given twice (compared as the loader canonicalises it: 2, 2.0 and 2e0 are one value).
void check_values(const SweepStudy& s) {
  for (const auto& k : s.sweep.keys) {
    std::vector<std::pair<std::string, std::string>> seen;  // canonical, as written
    for (const auto& v : k.values) {
      StudyArgs a = s.args;
      a.sets.push_back(k.key + "=" + v);
      std::string canonical;
      try {
        canonical = study::SweepSection::value_at(point_study(a), k.key);
      } catch (const UserError& e) {
        throw UserError(e.exit_code(), k.origin.where + ": the value " + clip(v) + " is refused: " + e.what());
      }
      for (const auto& [c, written] : seen)
        if (c == canonical)
          throw config_error(k.origin.where + ": the value " + clip(v) + " is given twice (first as " + clip(written) +
                             "); allowed: each value once (a point would run twice)");
      seen.emplace_back(canonical, v);
    }
  }
}

// A key both swept and set (--set) would run with the swept values only, the --set silently lost.
void check_swept_against_sets(const SweepStudy& s) {
  for (const auto& k : s.sweep.keys)
    for (const auto& set : s.args.sets)
      if (trim(set.substr(0, set.find('='))) == k.key)
        throw usage_error(k.origin.where + ": " + k.key + " is also given by --set " + clip(set) +
                          "; allowed: one of the two (a swept key takes its value from the sweep)");
}

// The point count, refused above the limit before anything else is done (counted in double: a
// crossed sweep's product may exceed any integer type).
void check_point_count(const SweepStudy& s, std::size_t limit) {
  double n = s.sweep.zipped ? static_cast<double>(s.sweep.keys.front().values.size()) : 1.0;
  std::string shape;
  for (const auto& k : s.sweep.keys) {
    shape += (shape.empty() ? "" : s.sweep.zipped ? ", " : " x ") + std::to_string(k.values.size()) + " " + k.key;
    if (!s.sweep.zipped) n *= static_cast<double>(k.values.size());
  }
  if (n > static_cast<double>(limit))
    throw config_error("the sweep of " + s.args.file + " has " + io::number_text(n) + " points (" +
                       (s.sweep.zipped ? "zipped: " : "crossed: ") + shape + "), more than " + std::to_string(limit) +
                       "; each point is one run of the study and one file in OUT.sweep; allowed: fewer values, or "
                       "--max-points N to run them all");
}

std::string point_path(const std::string& dir, std::size_t i) {
  const std::string name = io::formatted("point_%04zu.h5", i);
  return (fs::path(dir) / name).string();
}

// The sweep's work directory is a directory of rollspec's own that holds only point files and their
// checkpoints, and its manifest: a link, a file, a pipe or a user's file in it is not ours to write
// into or remove. Returns whether it exists.
constexpr const char* kManifest = "sweep.ini";  // the sweep's own study, for `run --resume --out` alone

bool ours(const std::string& name) { return name.rfind("point_", 0) == 0 || name.rfind(kManifest, 0) == 0; }

bool check_work_directory(const std::string& dir) {
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(dir, ec);
  if (st.type() == fs::file_type::not_found) return false;
  const std::string advice = "; move it away, or choose another --out";
  if (fs::is_symlink(st))
    throw cannot_create("sweep work directory " + dir + " is a symbolic link; rollspec keeps a sweep's points in a " +
                        "directory of its own" + advice);
  if (ec || !fs::is_directory(st))
    throw cannot_create("sweep work directory " + dir + " is not a directory (a file rollspec did not write)" + advice);
  for (fs::directory_iterator e(dir, ec), end; !ec && e != end; e.increment(ec))
    if (!ours(e->path().filename().string()))
      throw cannot_create("sweep work directory " + dir + " holds " + e->path().filename().string() +
                          ", which rollspec did not write" + advice);
  if (ec) throw cannot_create("cannot read sweep work directory " + dir + ": " + ec.message() + advice);
  return true;
}

// Whether the work directory holds no point yet (its manifest aside): nothing of the user's work.
bool no_points(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(dir, ec)) || ec) return false;
  for (fs::directory_iterator e(dir, ec), end; !ec && e != end; e.increment(ec))
    if (e->path().filename().string().rfind("point_", 0) == 0) return false;
  return !ec;
}

void remove_work_directory(const std::string& dir) {
  check_work_directory(dir);
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec) throw cannot_create("cannot remove sweep work directory " + dir + ": " + ec.message());
}

// Every rank reads the work directory before rank 0 changes it, so that all decide alike; rank 0
// alone removes it (--restart) and creates it, and every rank learns whether that failed.
// OUT.sweep/sweep.ini: the study file's path, then the resolved study with its [sweep]; written whole
// (a temporary renamed onto it), so that an interrupted sweep resumes from it without its study file.
void write_manifest(const std::string& dir, const SweepStudy& s) {
  const std::string path = (fs::path(dir) / kManifest).string(), temp = io::temp_name(path);
  io::register_temp(temp);
  {
    std::ofstream f(temp, std::ios::binary);
    f << "# rollspec sweep of " << fs::absolute(s.args.file).string() << "\n" << s.study_text;
    if (!f.flush()) {
      f.close();
      std::remove(temp.c_str());
      io::unregister_temp(temp);
      throw cannot_create("cannot write " + path + " (no space left on device?)");
    }
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) std::remove(temp.c_str());
  io::unregister_temp(temp);
  if (ec) throw cannot_create("cannot write " + path + ": " + ec.message());
}

void prepare_work_directory(const std::string& dir, const std::string& out, const RunRequest& q, const SweepStudy& s) {
  const bool unfinished = check_work_directory(dir);
  if (unfinished && !q.resume && !q.restart)
    throw cannot_create("an unfinished sweep of " + out + " is in " + dir +
                        "; allowed: --resume to finish it, or --restart to discard it");
  ensemble::mpi_barrier();
  std::string failure;
  if (ensemble::mpi_rank() == 0) {
    try {
      if (unfinished && q.restart) remove_work_directory(dir);
      std::error_code ec;
      fs::create_directory(dir, ec);  // not its parents: a missing directory of OUT is refused as run refuses it
      if (ec) throw cannot_create("cannot create sweep work directory " + dir + ": " + ec.message());
      if (!s.from_manifest) write_manifest(dir, s);
    } catch (const UserError& e) {
      failure = e.what();
      // A directory made here whose manifest could not be written (a full disk) holds no point: gone
      // again, so that the next run is not asked for --resume.
      if (no_points(dir)) {
        std::error_code ec;
        fs::remove_all(dir, ec);
      }
    }
  }
  if (ensemble::any_rank(!failure.empty()))
    throw cannot_create(failure.empty() ? "rank 0 could not prepare the sweep work directory " + dir : failure);
}

io::StackAxis axis_of(const SweepStudy& s, const study::SweptKey& k) {
  io::StackAxis a{k.dimension, k.unit == "-" ? "1" : k.unit, "swept study key " + k.key, {}, {}};
  for (const auto& v : k.values) {
    StudyArgs args = s.args;
    args.sets.push_back(k.key + "=" + v);
    a.texts.push_back(study::SweepSection::value_at(point_study(args), k.key));
  }
  for (const auto& t : a.texts) {
    char* end = nullptr;
    const double x = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end) return a;
    a.numbers.push_back(x);
  }
  a.texts.clear();
  return a;
}

// A finished point file is kept on --resume only if it is the result of that point's study.
bool finished_point(const std::string& path, const study::Study& s) {
  if (!fs::exists(path) || fs::exists(path + ".checkpoint")) return false;
  const io::Hdf5Reader r(path);
  if (r.has_attribute("/", "study") && r.string_attribute("/", "study") == s.canonical_text()) return true;
  throw data_error("sweep point file " + path + " holds the result of a different study (the study or its sweep " +
                   "changed since it ran); rerun with --restart");
}

std::string changed_keys(const SweepStudy& s, std::size_t i) {
  const auto a = s.sweep.point_sets(0), b = s.sweep.point_sets(i);
  std::string out;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k] != b[k]) out += (out.empty() ? "" : "; ") + s.sweep.keys[k].origin.where;
  return out;
}

void run_point(const SweepStudy& s, const RunRequest& q, std::size_t i, const std::string& path) {
  RunRequest pq = q;
  pq.study = s.point(i);
  pq.out = path;
  pq.resume = q.resume && fs::exists(path + ".checkpoint");
  pq.restart = false;
  if (s.from_manifest && pq.resume) pq.study.file.clear();  // the point's checkpoint holds its own study
  ResolvedRun run = resolve_run(pq);
  check_resources(run.study, q.force);
  if (run.scene->kind == scenes::SceneKind::single_run)
    run_single_phase(run, pq);
  else
    run_ensemble_phase(run, pq);
}

}  // namespace

StudyArgs SweepStudy::point(std::size_t i) const {
  StudyArgs a = args;
  for (const auto& set : sweep.point_sets(i)) a.sets.push_back(set);
  return a;
}

std::string SweepStudy::label(std::size_t i) const {
  std::string out;
  for (const auto& set : sweep.point_sets(i)) out += (out.empty() ? "" : ", ") + set;
  return out;
}

study::Study load_study_without_sweep(const std::string& file, const std::vector<std::string>& sets,
                                      const std::string& study_text) {
  const auto text = study_text.empty() ? read_text(file) : std::optional<std::string>(study_text);
  StudyArgs a{file, sets, text.value_or("")};
  if (!text || study::split_sweep(file, a.text).empty())
    return study_text.empty() ? study::Study::load(file, sets, scenes::schema_for)
                              : study::Study::parse(file, study_text, sets, scenes::schema_for);
  return point_study(a);
}

std::optional<SweepStudy> load_sweep(const StudyArgs& args, const std::vector<std::string>& sweeps,
                                     const SweepLimits& limits) {
  if (args.file.empty()) {
    if (!sweeps.empty()) throw usage_error("--sweep needs the study file");
    return std::nullopt;
  }
  SweepStudy s{args, {}, {}};
  if (s.args.text.empty()) {
    const auto text = read_text(args.file);
    if (!text) return std::nullopt;  // too large for a study: the ordinary loader refuses it
    s.args.text = *text;
  }
  const std::vector<study::SweepLine> lines = study::split_sweep(args.file, s.args.text);
  if (lines.empty() && sweeps.empty()) {
    if (s.args.text.find("[sweep]") == std::string::npos) return std::nullopt;
  }
  const study::Study base = point_study(s.args);
  s.sweep = study::SweepSection::parse(args.file, lines, sweeps, base);
  if (s.sweep.empty())
    throw config_error(args.file + ": [sweep] names no keys; allowed: section.key = v1, v2, ... (or remove [sweep])");
  check_swept_against_sets(s);
  check_point_count(s, limits.max_points);
  if (limits.announce && ensemble::mpi_rank() == 0)
    std::cout << "sweep of " << args.file << ": " << s.points() << " point" << (s.points() == 1 ? "" : "s") << " ("
              << (s.sweep.zipped ? "zipped" : "crossed") << "), each one run of the study; checking every value, "
              << "result shape and memory estimate before the first point runs\n"
              << std::flush;
  check_values(s);
  check_sweep_points(s, limits.force);
  s.study_text = base.canonical_text() + "\n[sweep]\nmode = " + (s.sweep.zipped ? "zipped" : "crossed") + "\n";
  for (const auto& k : s.sweep.keys) {
    std::string v;
    for (const auto& x : k.values) v += (v.empty() ? "" : ", ") + x;
    s.study_text += k.key + " = " + v + "\n";
  }
  return s;
}

std::optional<SweepStudy> load_sweep_manifest(const std::string& out, const SweepLimits& limits) {
  std::error_code ec;
  const fs::path target = fs::is_symlink(out, ec) ? fs::canonical(out, ec) : fs::path(out);
  const std::string dir = (ec ? fs::path(out) : target).string() + ".sweep";
  if (!check_work_directory(dir)) return std::nullopt;
  const std::string path = (fs::path(dir) / kManifest).string();
  if (!fs::is_regular_file(fs::symlink_status(path, ec)))
    throw missing_input("no study file given, and " + dir +
                        " holds no sweep manifest (written by an older rollspec); resume with the study file: "
                        "rollspec run STUDY.ini --out " +
                        out + " --resume");
  const auto text = read_text(path);
  if (!text || text->rfind("# rollspec sweep of ", 0) != 0)
    throw data_error(path + ": not a sweep manifest rollspec wrote; resume with the study file");
  const std::size_t eol = text->find('\n');
  StudyArgs args{text->substr(20, eol == std::string::npos ? std::string::npos : eol - 20),
                 {},
                 eol == std::string::npos ? std::string() : "\n" + text->substr(eol + 1)};
  SweepLimits l = limits;
  l.max_points = SIZE_MAX;  // accepted when it started
  auto s = load_sweep(args, {}, l);
  if (!s) throw data_error(path + ": holds no [sweep]; resume with the study file");
  s->from_manifest = true;
  return s;
}

int run_sweep(const SweepStudy& s, const RunRequest& q) {
  if (q.only >= 0) throw usage_error("--only runs one realisation of one study; it takes no sweep");
  const std::string out = q.out.empty() ? fs::path(s.args.file).stem().string() + ".h5" : q.out;
  io::OutputTarget target{out, io::kResultFileType};
  target.force = q.force;
  target.clean_stale = ensemble::mpi_rank() == 0;
  target.inputs = point_study(s.args).input_files();
  const std::string write_path = io::check_output_target(target);
  const std::string dir = write_path + ".sweep";
  prepare_work_directory(dir, out, q, s);
  const std::size_t n = s.points();
  std::vector<std::string> inputs;
  try {
    for (std::size_t i = 0; i < n; ++i) {
      const std::string path = point_path(dir, i);
      inputs.push_back(path);
      if (!q.quiet && ensemble::mpi_rank() == 0)
        std::cout << "sweep point " << i + 1 << " of " << n << ": " << s.label(i) << "\n" << std::flush;
      if (q.resume && finished_point(path, point_study(s.point(i)))) {
        if (!q.quiet && ensemble::mpi_rank() == 0) std::cout << "  finished before: kept " << path << "\n";
      } else {
        run_point(s, q, i, path);
      }
      if (ensemble::stop_requested())
        throw UserError(130, "interrupted after sweep point " + std::to_string(i + 1) + " of " + std::to_string(n) +
                                 "; rollspec run --resume finishes the sweep");
      // A key that changes a dataset's shape is refused at its first point that does, not after the last.
      if (i > 0 && ensemble::mpi_rank() == 0) {
        const std::string why = io::stack_difference(inputs[0], path);
        if (!why.empty())
          throw config_error(changed_keys(s, i) + ": " + why +
                             "; allowed: sweeps of keys that keep every dataset's shape and coordinates");
      }
    }
  } catch (...) {
    // A sweep that failed before any of its work reached the disk (a full disk) leaves no empty work
    // directory that would make the next run ask for --resume.
    std::error_code empty_ec;
    if (ensemble::mpi_rank() == 0 && no_points(dir)) fs::remove_all(dir, empty_ec);
    throw;
  }
  if (ensemble::mpi_rank() != 0) return 0;
  io::StackRequest r;
  r.inputs = inputs;
  r.mode = s.sweep.zipped ? "zipped" : "crossed";
  r.study_text = s.study_text;
  r.what = "the sweep of " + s.args.file;
  for (std::size_t k = 0; k < s.sweep.keys.size(); ++k)
    (s.sweep.zipped && k > 0 ? r.coordinates : r.axes).push_back(axis_of(s, s.sweep.keys[k]));
  {
    const ensemble::CriticalSection finishing;
    io::stack_results(r, write_path);
    remove_work_directory(dir);
  }
  if (!q.quiet) std::cout << "wrote " << out << " (sweep of " << n << " point" << (n == 1 ? "" : "s") << ")\n";
  return 0;
}

}  // namespace rollspec::run
