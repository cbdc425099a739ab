#include "src/io/sweep_point.hpp"

#include <algorithm>
#include <cstdlib>

#include "src/error.hpp"
#include "src/io/number_text.hpp"
#include "src/text_trim.hpp"

namespace rollspec::io {

namespace {

struct SweptAxis {
  std::string dimension, key;      // "oscillator_mass", "oscillator.mass"
  std::vector<std::string> texts;  // the values as text
  std::vector<double> numbers;     // and as numbers, when they are
};

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(by, start);
    out.push_back(trim(text.substr(start, at == std::string::npos ? std::string::npos : at - start)));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

SweptAxis read_axis(const Hdf5Reader& r, const std::string& dimension) {
  SweptAxis a{dimension, dimension, {}, {}};
  const std::string path = "/sweep/" + dimension;
  if (!r.exists(path))
    throw data_error(r.path() + ": /sweep@keys names " + dimension + ", but " + path + " is missing");
  if (r.has_attribute(path, "description")) {
    const std::string d = r.string_attribute(path, "description"), prefix = "swept study key ";
    if (d.rfind(prefix, 0) == 0) a.key = d.substr(prefix.size());
  }
  try {
    a.numbers = r.read(path);
    for (const double v : a.numbers) a.texts.push_back(number_text(v));
  } catch (const UserError&) {
    a.texts = r.read_strings(path);
  }
  if (a.texts.empty()) throw data_error(r.path() + ": " + path + " holds no values");
  return a;
}

std::string describe(const std::vector<SweptAxis>& axes, bool zipped, std::size_t n) {
  std::string s;
  for (const auto& a : axes) {
    std::string values;
    for (std::size_t i = 0; i < a.texts.size() && i < 8; ++i) values += (i ? ", " : "") + clip(a.texts[i], 40);
    if (a.texts.size() > 8) values += ", ...";
    s += (s.empty() ? "" : zipped ? " with " : " x ") + a.key + " = " + values;
  }
  return std::to_string(n) + " points (" + (zipped ? "zipped: " : "crossed: ") + s + ")";
}

// The index of `value` among the axis's values (numbers compared as numbers), or npos.
std::size_t find_value(const SweptAxis& a, const std::string& value) {
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  const bool number = end != value.c_str() && *end == '\0' && !a.numbers.empty();
  for (std::size_t i = 0; i < a.texts.size(); ++i)
    if (number ? a.numbers[i] == x : a.texts[i] == value) return i;
  return std::string::npos;
}

}  // namespace

std::size_t SweepPoint::points() const {
  std::size_t n = 1;
  for (const auto s : shape) n *= s;
  return n;
}

SweepPoint sweep_point(const Hdf5Reader& r, const std::string& spec) {
  SweepPoint p;
  if (!r.exists("/sweep")) {
    if (!spec.empty())
      throw usage_error("point " + clip(spec) + ": " + r.path() +
                        " is not a sweep result (no /sweep); allowed: no point");
    return p;
  }
  const bool zipped = r.has_attribute("/sweep", "mode") && r.string_attribute("/sweep", "mode") == "zipped";
  std::vector<SweptAxis> axes;
  for (const auto& d : split(r.has_attribute("/sweep", "keys") ? r.string_attribute("/sweep", "keys") : "", ','))
    if (!d.empty()) axes.push_back(read_axis(r, d));
  if (axes.empty()) throw data_error(r.path() + ": /sweep names no swept key (/sweep@keys)");
  for (const auto& a : axes) {
    if (zipped && a.texts.size() != axes.front().texts.size())
      throw data_error(r.path() + ": the zipped sweep's keys have different numbers of values");
    if (!zipped || p.shape.empty()) p.shape.push_back(a.texts.size());
  }
  const std::size_t n = p.points();
  const std::string allowed = "; allowed: a point K from 1 to " + std::to_string(n) +
                              " (run order), or section.key=value[,...] naming its swept values";
  if (spec.empty())
    throw usage_error(r.path() + " is a sweep result of " + describe(axes, zipped, n) + "; choose one point" + allowed);
  std::vector<std::size_t> index(p.shape.size(), std::string::npos);
  if (spec.find_first_not_of("0123456789") == std::string::npos && spec.size() < 16) {
    const std::size_t k = std::stoull(spec);
    if (k < 1 || k > n)
      throw usage_error("point " + spec + ": " + r.path() + " has " + describe(axes, zipped, n) + allowed);
    p.offset = k - 1;
  } else {
    for (const auto& item : split(spec, ',')) {
      const std::size_t eq = item.find('=');
      const std::string key = trim(item.substr(0, eq)),
                        value = eq == std::string::npos ? "" : trim(item.substr(eq + 1));
      std::size_t axis = axes.size();
      for (std::size_t a = 0; a < axes.size(); ++a)
        if (axes[a].key == key || axes[a].dimension == key) axis = a;
      if (eq == std::string::npos || axis == axes.size())
        throw usage_error("point " + clip(spec) + ": '" + clip(item) + "' names no swept key of " + r.path() + " (" +
                          describe(axes, zipped, n) + ")" + allowed);
      const std::size_t i = find_value(axes[axis], value);
      const std::size_t slot = zipped ? 0 : axis;
      if (i == std::string::npos || (index[slot] != std::string::npos && index[slot] != i))
        throw usage_error("point " + clip(spec) + ": " + key + " = " + clip(value) + " is no point of " + r.path() +
                          " (" + describe(axes, zipped, n) + ")" + allowed);
      index[slot] = i;
    }
    p.offset = 0;
    for (std::size_t a = 0; a < index.size(); ++a) {
      if (index[a] == std::string::npos)
        throw usage_error("point " + clip(spec) + ": names no value of " + axes[a].key + " (" +
                          describe(axes, zipped, n) + ")" + allowed);
      p.offset = p.offset * p.shape[a] + index[a];
    }
  }
  std::size_t rest = p.offset;
  std::vector<std::string> parts(axes.size());
  for (std::size_t a = p.shape.size(); a-- > 0;) {
    const std::size_t i = rest % p.shape[a];
    rest /= p.shape[a];
    if (zipped)
      for (std::size_t k = 0; k < axes.size(); ++k) parts[k] = axes[k].key + "=" + axes[k].texts[i];
    else
      parts[a] = axes[a].key + "=" + axes[a].texts[i];
  }
  for (const auto& s : parts) p.label += (p.label.empty() ? "" : ", ") + s;
  return p;
}

std::vector<double> read_at_point(const Hdf5Reader& r, const SweepPoint& p, const std::string& name, std::size_t rank,
                                  std::vector<std::size_t>* dims) {
  std::vector<std::size_t> d;
  std::vector<double> v = r.read(name, &d);
  const std::size_t lead = p.shape.size();
  if (lead > 0 && d.size() != rank) {
    if (d.size() != rank + lead || !std::equal(p.shape.begin(), p.shape.end(), d.begin()))
      throw data_error(r.path() + ": " + name + " has neither the sweep's leading axes nor one point's shape");
    d.erase(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(lead));
    std::size_t block = 1;
    for (const auto s : d) block *= s;
    v = std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(p.offset * block),
                            v.begin() + static_cast<std::ptrdiff_t>((p.offset + 1) * block));
  }
  if (dims) *dims = d;
  return v;
}

}  // namespace rollspec::io
