#include "src/io/available_memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

namespace rollspec::io {

namespace {
double meminfo_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  return INFINITY;
}

double cgroup_headroom() {
  std::ifstream max_in("/sys/fs/cgroup/memory.max"), cur_in("/sys/fs/cgroup/memory.current");
  std::string max_text;
  double current = 0.0;
  if (!(max_in >> max_text) || max_text == "max" || !(cur_in >> current)) return INFINITY;
  return std::max(0.0, std::strtod(max_text.c_str(), nullptr) - current);
}

double address_space_headroom() {
  rlimit r{};
  if (getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return INFINITY;
  std::ifstream in("/proc/self/statm");
  double pages = 0.0;
  in >> pages;  // total program size
  return std::max(0.0, static_cast<double>(r.rlim_cur) - pages * 4096.0);
}

}  // namespace

double available_memory() { return std::min({meminfo_available(), cgroup_headroom(), address_space_headroom()}); }

}  // namespace rollspec::io
