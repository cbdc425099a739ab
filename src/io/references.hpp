#pragma once
// The papers and theory-note equations a computation used, recorded in its result's provenance as
// SurfaceTopography's @doi records them: one table here, each row an id as the code's comments cite it
// ("seed 001", "D-10", "ER-1..ER-7"), its citation and its DOI where one is known (else empty). Which
// rows a run used is the scene's to say (scene.hpp SceneInfo::references), from the study's choices.
#include <string>
#include <vector>

namespace rollspec::io {

class Hdf5Writer;
class Hdf5Reader;

struct Reference {
  std::string id;
  std::string citation;  // authors, title, venue and year; for an equation, its theory note and file
  std::string doi;       // empty where none could be verified
};

const std::vector<Reference>& reference_table();

// The row of `id`; an id not in the table is a programming error (std::logic_error naming it).
const Reference& find_reference(const std::string& id);

// "id | citation | doi" per id, in the order given, each id once.
std::vector<std::string> reference_lines(const std::vector<std::string>& ids);

// Writes /provenance/references, one string per reference_lines row.
void write_references(Hdf5Writer& w, const std::vector<std::string>& ids);

// The lines of a file's /provenance/references (none in a file written before it).
std::vector<std::string> read_reference_lines(const Hdf5Reader& r);

}  // namespace rollspec::io
