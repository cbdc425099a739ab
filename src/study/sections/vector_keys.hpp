#pragma once
// x,y,z values of text keys (scene rolling-beam): one triple, or several separated by ';'. Used by
// the section parsers only; a malformed item is refused at the key.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace rollspec::study {

class KeyReader;

Eigen::Vector3d vector3(const KeyReader& s, const std::string& key);
// ';'-separated x,y,z triples.
std::vector<Eigen::Vector3d> triples(const KeyReader& s, const std::string& key);

}  // namespace rollspec::study
