#pragma once
// Stacking result files of one shape into one file with leading axes (a parameter sweep): every
// dataset that differs between the inputs gains the leading axes, each a dimension scale in the
// dataset's group; datasets equal in every input are kept once. Inputs whose datasets differ in
// shape, names or coordinates (a dimension scale's values) are refused: they are not one array.
#include <cstddef>
#include <string>
#include <vector>

namespace rollspec::io {

struct StackAxis {
  std::string name, units, description;
  std::vector<double> numbers;     // the values when every one is a number
  std::vector<std::string> texts;  // else (and always for the /sweep attributes)
};

struct StackRequest {
  std::vector<std::string> inputs;     // in point order: the last leading axis varies fastest
  std::vector<StackAxis> axes;         // leading axes (their lengths multiply to inputs.size())
  std::vector<StackAxis> coordinates;  // extra coordinates along axis 0 (a zipped sweep), not axes
  std::string what;                    // names the swept keys in refusals: "swept key ball.speed"
  std::string mode;                    // /sweep@mode
  std::string study_text;              // replaces the root attribute `study`
};

// "" if `point` holds the same datasets with the same shapes and coordinates as `first`, else why
// not (naming the dataset).
std::string stack_difference(const std::string& first, const std::string& point);

// Writes the stacked file to `out` atomically (a temporary file renamed onto it).
void stack_results(const StackRequest& request, const std::string& out);

}  // namespace rollspec::io
