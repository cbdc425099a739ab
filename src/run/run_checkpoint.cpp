#include "src/run/run_checkpoint.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>

#include "src/run/sweep_run.hpp"
#include "src/ensemble/checkpoint.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/rank_failure.hpp"
#include "src/error.hpp"
#include "src/io/input_file.hpp"
#include "src/io/provenance.hpp"
#include "src/scenes/scene.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::run {

namespace {

std::string list_names(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < 5; ++i) s += (i ? ", " : "") + clip(names[i], 80);
  if (names.size() > 5) s += ", ... (" + std::to_string(names.size()) + " in all)";
  return s;
}

std::string show_key(const std::string& full) {
  const auto dot = full.find('.');
  return "[" + full.substr(0, dot) + "] " + full.substr(dot + 1);
}

bool finishing(const std::string& key) {
  const auto& keys = scenes::finishing_keys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string finishing_list() {
  std::string out;
  for (const auto& k : scenes::finishing_keys()) out += (out.empty() ? "" : ", ") + show_key(k);
  return out;
}

// The study a --resume runs: the checkpoint's. Refuses other --set values and a changed study file,
// except for the finishing keys (scene.hpp): the chunks do not depend on them.
study::Study resume_study(const study::Study& asked, const std::vector<std::string>& sets,
                          const ensemble::CheckpointManifest& m, const std::string& dir, bool from_checkpoint,
                          const std::string& text) {
  std::map<std::string, std::string> stored;
  for (const auto& [k, v] : ensemble::canonical_entries(m.study_text)) stored[k] = v;
  std::string differ;
  for (const auto& o : asked.overrides()) {
    const auto eq = o.find('=');
    const std::string key = o.substr(0, eq), value = o.substr(eq + 1);
    const auto it = stored.find(key);
    if (it != stored.end() && finishing(key)) continue;
    if (it == stored.end() || it->second != value)
      differ += "\n  " + show_key(key) + ": --set " + clip(value, 80) + ", the checkpoint has " +
                (it == stored.end() ? std::string("no such key") : clip(it->second, 80));
  }
  if (!differ.empty())
    throw data_error(dir + ": the checkpoint belongs to a different study, written with other settings:" + differ +
                     "\nthe checkpointed chunks were computed with these values; only " + finishing_list() +
                     " may change on --resume (they are computed after the ensemble); resume without these --set "
                     "(the checkpoint's settings are reused), or start over with --restart");
  if (from_checkpoint) return asked;  // parsed from this manifest: nothing on disk to compare with
  std::vector<std::string> all = m.sets;
  all.insert(all.end(), sets.begin(), sets.end());
  study::Study s = load_study_without_sweep(asked.file(), all, text);
  std::map<std::string, std::string> current;
  for (const auto& [k, v] : ensemble::canonical_entries(s.canonical_text())) current[k] = v;
  std::string keys;
  for (const auto& [k, v] : current) {
    const auto it = stored.find(k);
    if (it == stored.end() || (it->second != v && !finishing(k)))
      keys += "\n  " + show_key(k) + " = " + clip(v, 80) +
              " (checkpoint: " + (it == stored.end() ? std::string("absent") : clip(it->second, 80)) + ")";
  }
  for (const auto& [k, v] : stored)
    if (!current.count(k)) keys += "\n  " + show_key(k) + " absent (checkpoint: " + clip(v, 80) + ")";
  if (!keys.empty())
    throw data_error(dir + ": the checkpoint belongs to a different study (the study file changed):" + keys +
                     "\nresume with the study it was written for, or start over with --restart");
  return s;
}

void check_directory(const std::string& dir) {
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0) return;
  if (!S_ISDIR(st.st_mode))
    throw cannot_create(
        "checkpoint " + dir + " exists and is " +
        (S_ISLNK(st.st_mode) ? std::string("a symbolic link") : std::string(io::file_kind(st.st_mode))) +
        ", not a checkpoint directory rollspec wrote; move it away or choose another --out");
  const auto foreign = ensemble::CheckpointStore(dir, 0).foreign_entries();
  if (!foreign.empty())
    throw cannot_create("checkpoint directory " + dir + " holds files rollspec did not write (" + list_names(foreign) +
                        "); rollspec never removes them: move them away or choose another --out");
}

}  // namespace

study::Study checkpoint_study(const std::string& dir, const std::vector<std::string>& sets) {
  const auto m = ensemble::read_manifest(dir);
  if (!m)
    throw missing_input("no study file given, and " + dir +
                        " holds no checkpoint to resume; allowed: rollspec run STUDY.ini "
                        "[--out FILE.h5], or rollspec run --resume --out FILE.h5 where FILE.h5.checkpoint exists");
  if (m->study_file.empty())
    throw data_error(dir +
                     ": this checkpoint does not record its study file (written by an older rollspec); resume with "
                     "the study file: rollspec run STUDY.ini --out ... --resume");
  return study::Study::parse(m->study_file, m->study_text, sets, scenes::schema_for);
}

CheckpointSession open_checkpoint(const std::string& dir, study::Study& s, const std::vector<std::string>& sets,
                                  bool resume, bool restart, bool quiet, bool study_from_checkpoint,
                                  const std::string& study_text) {
  CheckpointSession session;
  session.directory = dir;
  std::exception_ptr failure;
  const bool root = ensemble::mpi_rank() == 0;
  try {
    check_directory(dir);
    if (root) session.lock = std::make_unique<ensemble::CheckpointLock>(dir);
    check_directory(dir);  // again under the lock
    const ensemble::CheckpointStore store(dir, 0);
    const auto manifest = ensemble::read_manifest(dir);
    const std::size_t chunks = store.chunk_count();
    if (resume && manifest) {
      if (manifest->identity != io::code_identity())
        throw data_error(dir + ": the checkpoint was written by another build (" + manifest->identity + "); this is " +
                         io::code_identity() +
                         "; results of two code versions are never mixed: start over with --restart");
      s = resume_study(s, sets, *manifest, dir, study_from_checkpoint, study_text);
      if (!quiet && root && !manifest->sets.empty()) {
        std::string list;
        for (const auto& o : manifest->sets) list += " --set " + o;
        std::cerr << "resuming with the checkpoint's settings:" << list << "\n";
      }
    } else if (resume && chunks) {
      throw data_error(dir +
                       ": the checkpoint has chunks but no manifest (written by an older rollspec, or "
                       "damaged); start over with --restart");
    } else if (chunks && !restart) {
      throw cannot_create(dir + " holds an unfinished run (" + std::to_string(chunks) + " checkpointed chunk" +
                          (chunks == 1 ? "" : "s") + "); finish it with --resume, or start over with --restart");
    }
    if (root && !(resume && manifest)) {
      store.clear(/*keep_lock=*/true);  // stale chunks (--restart), temporaries, an old manifest
      ensemble::write_manifest(
          dir, {io::code_identity(), s.overrides(), s.canonical_text(), std::filesystem::absolute(s.file()).string()});
    }
  } catch (...) {
    failure = std::current_exception();
  }
  ensemble::rethrow_on_every_rank(failure, "stopped because another rank failed (see its message)");
  return session;
}

}  // namespace rollspec::run
