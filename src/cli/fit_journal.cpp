#include "src/cli/fit_journal.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/io/provenance.hpp"
#include "src/io/temp_files.hpp"

namespace rollspec::cli {

namespace {

constexpr const char* kHeader = "# rollspec fit journal ";

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(const std::string& s) {
    for (const unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // a separator: ("ab", "c") differs from ("a", "bc")
  }
  void add(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    add(std::string(buf));
  }
  void add_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    add(s.str());
  }
};

std::string hex(std::uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

}  // namespace

std::uint64_t fit_journal_key(const FitInputs& in, const std::string& column) {
  Fnv f;
  f.add(io::code_identity());
  f.add_file(in.study);
  for (const auto& s : in.sets) f.add("set " + s);
  for (const auto& v : in.vary) f.add(v.key), f.add(v.lo), f.add(v.hi), f.add(v.log ? "log" : "linear");
  f.add("sensor " + in.sensor.name), f.add(in.sensor.position ? *in.sensor.position : NAN);
  f.add("column " + column), f.add(in.fmin), f.add(in.fmax);
  for (const auto& p : in.points) f.add_file(p.path), f.add("at " + p.at), f.add(p.records);
  return f.h;
}

FitJournal::FitJournal(std::string path, std::uint64_t key) : path_(std::move(path)), key_(key) {
  std::ifstream f(path_);
  if (!f) return;
  std::string line;
  const std::string expected = kHeader + hex(key_);
  if (!std::getline(f, line) || line.rfind(kHeader, 0) != 0)
    throw cannot_create("--journal " + path_ +
                        ": not a rollspec fit journal; allowed: a new file or the journal of "
                        "this fit (remove it or choose another path)");
  if (line != expected)
    throw cannot_create("--journal " + path_ +
                        ": the journal of another fit (its study, measurements, options or build differ); allowed: "
                        "the journal of this fit, or a new file (remove it or choose another path)");
  for (int number = 2; std::getline(f, line); ++number) {
    std::istringstream s(line);
    std::vector<double> row;
    for (std::string word; s >> word;) {
      char* end = nullptr;
      row.push_back(std::strtod(word.c_str(), &end));
      if (*end != '\0') row.clear(), s.setstate(std::ios::failbit);
    }
    if (row.size() < 2)
      throw data_error(path_ + ":" + std::to_string(number) + ": not a line of parameter values and -ln L");
    const double value = row.back();
    row.pop_back();
    order_.emplace_back(row, value);
    entries_.emplace(row, value);
  }
}

bool FitJournal::find(const std::vector<double>& u, double& value) const {
  const auto hit = entries_.find(u);
  if (hit == entries_.end()) return false;
  value = hit->second;
  return true;
}

void FitJournal::record(const std::vector<double>& u, double value) {
  order_.emplace_back(u, value);
  entries_.emplace(u, value);
  const std::string temp = io::temp_name(path_);
  io::register_temp(temp);
  {
    std::ofstream out(temp);
    out << kHeader << hex(key_) << "\n";
    char buf[32];
    for (const auto& [x, v] : order_) {
      for (const double c : x) std::snprintf(buf, sizeof buf, "%.17g ", c), out << buf;
      std::snprintf(buf, sizeof buf, "%.17g\n", v);
      out << buf;
    }
    if (!out.flush()) throw cannot_create("--journal " + path_ + ": cannot write " + temp);
  }
  const ensemble::CriticalSection keep;  // an interrupt waits for the rename
  std::error_code ec;
  std::filesystem::rename(temp, path_, ec);
  io::unregister_temp(temp);
  if (ec) throw cannot_create("--journal " + path_ + ": cannot rename " + temp + " onto it: " + ec.message());
}

}  // namespace rollspec::cli
