#pragma once
// Every length, thickness, radius, rms and speed of a study checked against the others before any
// work, each relation with its physical reason: a value written in mm or um where the key is in m
// (10^3 or 10^6 too large) breaks the relations it takes part in, and the key they share is named.
//
// Each relation is a physical statement about a few keys (a beam thinner than its span, a ball
// narrower than its beam, a rough surface flatter than 45 degrees). When some fail, the key named is
// the one the failed relations have in common: the one the user wrote (a default cannot be a slip),
// in the most failed relations; where that leaves a tie, the one furthest (in decades) from its
// documented default, and the message names the other keys of the relation beside it.
#include <string>
#include <vector>

namespace rollspec::study {
class KeyReader;
}

namespace rollspec::scenes {

struct DimensionRelation {
  std::vector<std::string> keys;  // "section.key", the likelier culprit first
  bool holds = true;
  std::string why;  // the physical reason, with the values it compares
};

// Refuses (exit 78, naming the key: config_error through KeyReader::refuse) a study whose relations
// fail; returns quietly otherwise.
void refuse_failed_relations(const study::KeyReader& s, const std::vector<DimensionRelation>& relations);

// The relations of the study's scene, checked. Called once a study is loaded (cli/run_phases.cpp:
// resolve_study), before anything is made from it.
void check_dimensions(const study::KeyReader& s);

// Each scene's own relations are its registry row's `relations` (in its package folder).

// Shared by the scenes' relations: "0.39 m"; the relations of [texture] (a self-affine source) with
// the length `span` that holds its profile (named by `span_key`), and of [surface] (its grid against
// the Hertz contact radius when it carries a contact, > 0); the ball's Hertz radius under its weight.
std::string dim(double v, const char* unit);
// Whether the study writes any self-affine [texture] key (checked even where no texture is drawn).
bool self_affine_written(const study::KeyReader& s);
void add_texture_relations(const study::KeyReader& s, const std::string& span_key, double span,
                           const std::string& span_what, std::vector<DimensionRelation>& out);
// contact_grid: the grid is a contact's (the half-space solver's, the tube's floor), which needs a continuum
// in each cell; the texture scene's grid is only where heights are drawn (an AFM's, below 10 nm, too).
void add_surface_relations(const study::KeyReader& s, bool rough, double contact_radius,
                           std::vector<DimensionRelation>& out, bool contact_grid = true);
double e_star(double e1, double nu1, double e2, double nu2);
double hertz_radius(const study::KeyReader& s, double e, double nu);
void ball_relations(double a, double r, std::vector<DimensionRelation>& out);
void approach_relations(const study::KeyReader& s, double a, std::vector<DimensionRelation>& out);

}  // namespace rollspec::scenes
