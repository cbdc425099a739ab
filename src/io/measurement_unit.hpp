#pragma once
// Units of measured signals, read from what loggers write: a column name (`Acc (g)`, `a [m/s²]`,
// `time_ms`, `t [µs]`, `a/(m/s^2)`) or a cell of a units row (`[s]`, `m/s2`, `(g)`). A closed list,
// spelled as loggers spell it: `²`, `^2`, `2`, `/s/s`, `s^-2`, `s⁻²`; `µ` (micro sign), `μ` (Greek
// mu) or `u`; ISO-8859-1 bytes for `²` and `µ` as Windows exports write them; case ignored.
//   acceleration: g (also gn; 9.80665 m/s² per g), m/s², cm/s², mm/s², µm/s², in/s², ft/s²
//   time:         s (sec), ms (msec), µs (us, usec), ns
//   other:        what is known to be no acceleration (V, mV, N, Pa, Hz, °C, m/s, mm, %, -, ...):
//                 a channel in one is refused unless --unit says otherwise
#include <optional>
#include <string>

namespace rollspec::io {

enum class Quantity { acceleration, time, other };

struct MeasurementUnit {
  std::string text;  // canonical spelling: "g", "m/s^2", "mm/s^2", "ms", "us", "V"
  Quantity quantity = Quantity::other;
  double factor = 1.0;  // m/s² per unit (acceleration), s per unit (time); 1 for other units
};

// A unit as written, optionally in one pair of brackets: "g", "[m/s²]", "(ms)", "m s^-2". nullopt if
// it is no unit of the list above.
std::optional<MeasurementUnit> parse_measurement_unit(const std::string& text);

// A PSD unit of acceleration, as written in a column title: (m/s^2)^2/Hz, g^2/Hz, (mm/s²)²/Hz, g2/Hz,
// m2/s4/Hz; `factor` is (m/s²)²/Hz per unit (96.17 for g^2/Hz). nullopt if it is none of these.
std::optional<MeasurementUnit> parse_psd_unit(const std::string& text);

// What a column name says: its name without the unit (`base`) and the unit.
struct NamedUnit {
  std::string base;                     // "Acc" of "Acc (g)"; the whole name if it carries no unit
  std::string written;                  // the unit as written in the name ("g", "m/s²"), or the bracket's
                                        // text when that is no known unit ("sensor 2" of "acc (sensor 2)")
  std::optional<MeasurementUnit> unit;  // nullopt: no known unit in the name
  bool bracketed = false;               // the unit (or unknown text) came in [] or () at the end
};

// Units recognised in names: at the end in [] or (), after a '/' (DIN 1313: `a/(m/s^2)`, `time/ms`),
// after the last '_' (acceleration and time units only: `acc_g`, `time_ms`, not `pair_1`), or as
// the last word when it cannot be a word (`Acceleration m/s^2`).
NamedUnit unit_in_name(const std::string& name);

// A cell of a units row: empty, bracketed, or a unit of the list.
bool units_row_cell(const std::string& cell);

// True if the name without its unit names a time: t, time, zeit, temps, tiempo, tempo, tijd, tid
// (case and spaces ignored; a bare capital T, with no unit, is a temperature or tension as often).
bool time_like_name(const NamedUnit& n, const std::string& name);

// Accepted --unit values, for messages.
constexpr const char* kAccelerationUnits = "g, m/s2 (also m/s^2), cm/s2, mm/s2, um/s2, in/s2, ft/s2";

}  // namespace rollspec::io
