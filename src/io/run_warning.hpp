#pragma once
// Warnings about a run's validity (suspect keys, loss of contact, too few realisations for a band's
// tail) go through warn(), printed on stderr even when quiet. A command that runs a study many times
// (fit) gathers them with a RunWarningCapture instead, and says the ones that matter once.
#include <string>
#include <vector>

namespace rollspec::io {

// Prints "rollspec: warning: TEXT" ("WARNING" when loud), or hands it to the capture in force.
void warn(const std::string& text, bool loud = false);

// While one is alive, warn() appends its lines here instead of printing them; an inner capture (a
// jackknife run inside a fit) takes them while it lives, then hands warn() back to the outer one.
class RunWarningCapture {
 public:
  RunWarningCapture();
  ~RunWarningCapture();
  RunWarningCapture(const RunWarningCapture&) = delete;
  RunWarningCapture& operator=(const RunWarningCapture&) = delete;
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  std::vector<std::string> lines_;
  std::vector<std::string>* outer_;
};

}  // namespace rollspec::io
