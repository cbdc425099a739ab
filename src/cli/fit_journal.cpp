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
  f.add(in.same_surface ? "same surface" : "new surface");
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
    const auto bar = line.find(';');
    std::vector<double> point, values;
    bool ok = bar != std::string::npos;
    for (int half = 0; half < 2 && ok; ++half) {
      std::istringstream s(half == 0 ? line.substr(0, bar) : line.substr(bar + 1));
      auto& row = half == 0 ? point : values;
      for (std::string word; s >> word;) {
        char* end = nullptr;
        row.push_back(std::strtod(word.c_str(), &end));
        if (*end != '\0') ok = false;
      }
      ok = ok && !row.empty();
    }
    if (!ok)
      throw data_error(path_ + ":" + std::to_string(number) +
                       ": not a line of an evaluation's key and values (numbers, then ';', then numbers)");
    order_.emplace_back(point, values);
    entries_.emplace(point, values);
  }
}

bool FitJournal::find(const std::vector<double>& key, std::vector<double>& values) const {
  const auto hit = entries_.find(key);
  if (hit == entries_.end()) return false;
  values = hit->second;
  return true;
}

void FitJournal::record(const std::vector<double>& key, const std::vector<double>& values) {
  order_.emplace_back(key, values);
  entries_.emplace(key, values);
  const std::string temp = io::temp_name(path_);
  io::register_temp(temp);
  {
    std::ofstream out(temp);
    out << kHeader << hex(key_) << "\n";
    char buf[32];
    for (const auto& [x, v] : order_) {
      for (const double c : x) std::snprintf(buf, sizeof buf, "%.17g ", c), out << buf;
      out << ";";
      for (const double c : v) std::snprintf(buf, sizeof buf, " %.17g", c), out << buf;
      out << "\n";
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
