#include "src/io/run_warning.hpp"

#include <cstdio>
#include <mutex>

namespace rollspec::io {
namespace {
std::mutex capture_mutex;
std::vector<std::string>* capture = nullptr;
}  // namespace

void warn(const std::string& text, bool loud) {
  const std::string line = std::string(loud ? "rollspec: WARNING: " : "rollspec: warning: ") + text;
  const std::lock_guard<std::mutex> lock(capture_mutex);
  if (capture)
    capture->push_back(line);
  else
    std::fprintf(stderr, "%s\n", line.c_str());
}

RunWarningCapture::RunWarningCapture() {
  const std::lock_guard<std::mutex> lock(capture_mutex);
  outer_ = capture;
  capture = &lines_;
}

RunWarningCapture::~RunWarningCapture() {
  const std::lock_guard<std::mutex> lock(capture_mutex);
  capture = outer_;
}

}  // namespace rollspec::io
