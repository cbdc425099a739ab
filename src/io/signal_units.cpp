// Which unit each picked channel is read in: --unit, else what the file says (name, units row), else
// m/s², and in every case one line saying so. A value read in the wrong unit moves the whole PSD by a
// constant (g for m/s²: 19.8 dB) that no later check can see, so nothing here is silent.
#include <utility>

#include "src/error.hpp"
#include "src/io/measurement_unit.hpp"
#include "src/io/number_text.hpp"
#include "src/io/signal_file.hpp"

namespace rollspec::io {

std::vector<ChannelUnit> option_units(const std::string& units) {
  std::vector<ChannelUnit> out;
  std::size_t from = 0;
  for (;;) {
    const auto comma = units.find(',', from);
    const auto end = comma == std::string::npos ? units.size() : comma;
    const auto b = units.find_first_not_of(" \t", from);
    const auto e = units.find_last_not_of(" \t", end == 0 ? 0 : end - 1);
    const std::string one = b == std::string::npos || b >= end ? "" : units.substr(b, e - b + 1);
    const auto u = parse_measurement_unit(one);
    if (!u || u->quantity != Quantity::acceleration)
      throw usage_error("--unit " + clip(units) + (one == units ? "" : ": '" + clip(one) + "'") +
                        ": allowed: " + kSignalUnits);
    out.push_back(ChannelUnit{u->text, one, u->factor, UnitOrigin::option, "--unit", ""});
    if (comma == std::string::npos) return out;
    from = comma + 1;
  }
}

namespace {

// What the file says of channel i: the reader's finding, else (a .mat variable) its name's.
ChannelUnit file_unit(const SignalTable& s, std::size_t i) {
  if (i < s.units.size()) return s.units[i];
  ChannelUnit c;
  const NamedUnit n = unit_in_name(s.groups[i]);
  if (!n.unit || (!n.bracketed && n.unit->quantity == Quantity::time)) return c;
  c.text = n.unit->text;
  c.written = n.written;
  c.factor = n.unit->quantity == Quantity::acceleration ? n.unit->factor : 0.0;
  c.origin = UnitOrigin::name;
  c.where = "the name";
  return c;
}

std::string per_unit(const ChannelUnit& u) {
  return u.factor == 1.0 ? "" : " (" + number_text(u.factor) + " m/s^2 per " + u.text + ")";
}

std::string assumption(const SignalTable& s, const SignalRequest& r) {
  if (s.unit == "full scale")
    return "a sound file carries no unit: full scale (--scale " + number_text(r.scale) + ") taken as " +
           number_text(r.scale) + " m/s^2; --unit g if the recorder's full scale is " + number_text(r.scale) +
           " g (--unit takes " + kAccelerationUnits + ")";
  const std::string what = s.format.rfind("MATLAB", 0) == 0 ? "no unit in the variable's name"
                           : s.format.rfind("CSV", 0) == 0  ? "no unit in the column name or a units row"
                                                            : "a sound file carries no unit";
  return what + ": taken as m/s^2; --unit g if it holds g (--unit takes " + kAccelerationUnits + ")";
}

// One note per group of channels read the same way, in channel order.
void add_note(std::vector<std::pair<std::string, std::vector<std::string>>>& groups, const std::string& text,
              const std::string& channel) {
  for (auto& g : groups)
    if (g.first == text) {
      g.second.push_back(channel);
      return;
    }
  groups.push_back({text, {channel}});
}
}  // namespace

std::vector<ChannelUnit> choose_units(const SignalTable& s, const std::vector<std::size_t>& picked,
                                      const SignalRequest& r, std::vector<std::string>& notes) {
  const std::vector<ChannelUnit> option = r.unit.empty() ? std::vector<ChannelUnit>{} : option_units(r.unit);
  if (option.size() > 1 && option.size() != picked.size()) {
    std::string names;
    for (const auto i : picked) names += (names.empty() ? "" : ", ") + s.channels[i];
    throw usage_error("--unit " + clip(r.unit) + ": " + counted(option.size(), "unit") + " for " +
                      counted(picked.size(), "channel") + " (" + clip(names, 400) +
                      "); allowed: one unit for all channels, or one per channel in that order");
  }
  std::vector<ChannelUnit> out;
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  for (std::size_t k = 0; k < picked.size(); ++k) {
    const std::string& name = s.channels[picked[k]];
    const ChannelUnit f = file_unit(s, picked[k]);
    if (option.empty() && !f.conflict.empty()) throw data_error(f.conflict);
    if (!option.empty()) {
      out.push_back(option[option.size() == 1 ? 0 : k]);
      const auto& u = out.back();
      add_note(groups,
               "read in " + u.text + per_unit(u) + " (--unit" +
                   (f.origin == UnitOrigin::none ? ")"
                    : f.text == u.text           ? "; " + f.where + " says so too)"
                                                 : "; it overrides " + f.text + " by " + f.where + ")"),
               name);
    } else if (f.factor > 0.0) {
      out.push_back(f);
      add_note(groups, "read in " + f.text + per_unit(f) + " by " + f.where + "; --unit UNIT overrides it", name);
    } else if (f.origin != UnitOrigin::none) {
      throw data_error(s.file + ": channel '" + clip(name) + "' is in " + clip(f.text) + " by " + f.where +
                       ", not an acceleration; allowed: channels in " + kAccelerationUnits +
                       " (pick them with --column), or --unit UNIT if its values are accelerations after all");
    } else {
      out.push_back(ChannelUnit{"m/s^2", "", 1.0, UnitOrigin::assumed, "assumed", ""});
      add_note(groups, assumption(s, r), name);
    }
  }
  for (const auto& [text, names] : groups) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
    notes.push_back(s.file + ": " + clip(list, 300) + ": " + text);
  }
  return out;
}

}  // namespace rollspec::io
