#pragma once
// Stacking result files of one shape into one file with leading axes (a parameter sweep): every
// dataset that differs between the inputs gains the leading axes, each a dimension scale in the
// dataset's group; datasets equal in every input are kept once. Inputs whose datasets differ in
// shape, names or coordinates (a dimension scale's values) in a group that must stack (the
// result: /psd, /bands) are refused: they are not one array. Another top-level group that differs
// so (a diagnostic whose grid follows the record length, e.g. /roughness over the rolling speed)
// is kept per input, as /sweep/point_NNNN/<group>.
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
  std::vector<std::string> must_stack = {"/psd", "/bands"};  // groups that must stack, else refused
};

// "" if `point` holds the same datasets with the same shapes and coordinates as `first`, else why
// not (naming the dataset).
std::string stack_difference(const std::string& first, const std::string& point,
                             const std::vector<std::string>& must_stack = {"/psd", "/bands"});

// Writes the stacked file to `out` atomically (a temporary file renamed onto it).
void stack_results(const StackRequest& request, const std::string& out);

}  // namespace rollspec::io
