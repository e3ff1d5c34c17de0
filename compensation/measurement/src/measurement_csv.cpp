// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/machines/formatters.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ncpost::comp {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  return out;
}

struct Context {
  const std::string& file;
  int line;
  const std::string& text;
  [[noreturn]] void fail(const std::string& what, int column = 0) const {
    throw InputError({file, line, column}, what, text);
  }
};

double number(const std::string& field, const Context& where, const std::string& what) {
  double v = 0.0;
  const char* b = field.data();
  const char* e = field.data() + field.size();
  if (!field.empty() && *b == '+') ++b;
  auto [ptr, ec] = std::from_chars(b, e, v);
  if (field.empty() || ec != std::errc() || ptr != e)
    where.fail(fmt::format("expected a number for {}, found '{}'", what, field));
  if (!std::isfinite(v)) where.fail(fmt::format("{} is not finite ('{}')", what, field));
  return v;
}

Vec3d vector3(const std::string& value, const Context& where, const std::string& key) {
  const auto parts = split(value, ',');
  if (parts.size() != 3) where.fail(fmt::format("expected three comma-separated numbers (mm) for '{}'", key));
  return {number(parts[0], where, key), number(parts[1], where, key), number(parts[2], where, key)};
}

/// The largest deviation a reading of each instrument can show (README "Measurement files"): a
/// ballbar's measuring range is about ±1 mm, a probed sphere centre or a laser reading off by more
/// than 5 mm is a typing or export error, never a machine error the model could explain.
struct ReadingRange {
  MeasurementType type;
  double max_deviation;  ///< in the unit of the value column
  const char* unit;
};
constexpr ReadingRange kReadingRange[] = {
    {MeasurementType::ballbar, 2.0, "mm"},
    {MeasurementType::sphere, 5.0, "mm"},
    {MeasurementType::laser, 5000.0, "µm"},
};

const ReadingRange& reading_range(MeasurementType type) {
  for (const auto& r : kReadingRange)
    if (r.type == type) return r;
  return kReadingRange[0];
}

/// 1-based column of field `index` in the raw line (for messages).
int column_of_field(const std::string& raw, std::size_t index) {
  std::size_t at = 0;
  for (std::size_t k = 0; k < index; ++k) {
    const auto comma = raw.find(',', at);
    if (comma == std::string::npos) return 0;
    at = comma + 1;
  }
  while (at < raw.size() && (raw[at] == ' ' || raw[at] == '\t')) ++at;
  return static_cast<int>(at) + 1;
}

/// The temperatures a machine is measured at (°C); a value outside is a unit or typing error.
constexpr double kLowestTemperatureC = 0.0, kHighestTemperatureC = 50.0;
/// The largest linear expansion coefficient of a machine material (1/K; aluminium 23e-6).
constexpr double kLargestExpansionPerK = 50e-6;

/// The largest instrument uncertainty (µm, k = 2) and temperature uncertainty (K) a file may give.
constexpr double kLargestInstrumentUUm = 1000.0, kLargestTemperatureUK = 10.0;

/// A laser row's command off its file's '# line:' by more than this (mm) is refused.
constexpr double kOffLineMm = 1e-4;

/// The reading of one measurement CSV: metadata lines, the header (the type's keys and the
/// columns), then the rows; InputError at file:line:column for anything wrong.
class CsvParser {
 public:
  CsvParser(const std::string& file_name, const Machine& m, const CsvReadOptions& options)
      : file_(file_name), m_(m), options_(options), column_of_axis_(m.axes.size(), -1) {
    set_.file = file_name;
  }

  MeasurementSet parse(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    while (std::getline(in, raw)) {
      ++line_no_;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      const std::string line = trim(raw);
      const Context where{file_, line_no_, raw};
      if (line.empty()) continue;
      if (line[0] == '#') {
        metadata_line(line, raw);
      } else if (header_.empty()) {
        read_header(line, raw, where);
      } else {
        read_row(raw, where);
      }
    }
    if (header_.empty()) throw InputError({file_, line_no_, 0}, "no header line (expected e.g. 't,X,Y,Z,A,C,L')");
    if (set_.rows.empty())
      throw InputError({file_, header_line_, 0},
                       "no rows after the header: the file holds no measurements (was the export cut short?)");
    return std::move(set_);
  }

 private:
  /// A `#` line. Before the column line, `# key: value` with a key of letters, digits and `_`
  /// (starting with a letter) right before the colon is a key line; any other `#` line is a
  /// comment (docs/formats.md "Header keys and comments"). After the column line every `#` line is
  /// a comment; a known key there gets a notice (it is not read).
  void metadata_line(const std::string& line, const std::string& raw) {
    const std::string body = trim(line.substr(1));
    std::size_t end = 0;
    while (end < body.size() && (std::isalnum(static_cast<unsigned char>(body[end])) || body[end] == '_')) ++end;
    std::size_t colon = end;
    while (colon < body.size() && (body[colon] == ' ' || body[colon] == '\t')) ++colon;
    if (end == 0 || !std::isalpha(static_cast<unsigned char>(body[0])) || colon >= body.size() || body[colon] != ':')
      return;  // a comment
    const std::string key = body.substr(0, end);
    const Context where{file_, line_no_, raw};
    if (!header_.empty()) {
      if (known_key(key))
        notice(
            fmt::format("'# {}:' after the column line (line {}) is a comment there and is not read: header keys go "
                        "before the column line",
                        key, header_line_));
      return;
    }
    check_key(key, where);
    set_.metadata.emplace_back(key, trim(body.substr(colon + 1)));
    meta_lines_.push_back(line_no_);
  }

  static const HeaderKey* known_key(const std::string& key) {
    for (const HeaderKey& k : header_keys())
      if (key == k.name) return &k;
    return nullptr;
  }

  void notice(const std::string& text) { set_.notices.push_back(fmt::format("{}:{}: {}", file_, line_no_, text)); }

  /// A known key given twice or in other letter case is refused; an unknown key gets a notice.
  void check_key(const std::string& key, const Context& where) {
    if (known_key(key)) {
      if (const int first = key_line(key); first > 0)
        where.fail(fmt::format("'# {}:' given twice (first on line {}): which one holds? keep one", key, first));
      return;
    }
    std::string lower = key;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (known_key(lower)) where.fail(fmt::format("key '{}': header keys are lower case; write '# {}:'", key, lower));
    notice(
        fmt::format("unknown key '# {}:' kept with the file's metadata but not used (known keys: docs/formats.md "
                    "\"Measurement data\"; a comment has no 'word:' at its start)",
                    key));
  }

  int key_line(const std::string& key) const {
    for (std::size_t i = 0; i < set_.metadata.size(); ++i)
      if (set_.metadata[i].first == key) return meta_lines_[i];
    return 0;
  }

  std::string require(const std::string& key) const {
    const std::string v = set_.meta(key);
    if (v.empty()) {
      const int at = header_line_ > 0 ? header_line_ : line_no_;
      throw InputError({file_, at, 0},
                       fmt::format("missing required key '# {}:' for a {} file", key, to_string(set_.type)));
    }
    return v;
  }

  void read_header(const std::string& line, const std::string& raw, const Context& where) {
    header_line_ = line_no_;
    header_ = split(line, ',');
    read_type(where);
    read_type_keys(raw);
    read_conditions(raw);
    read_columns(where);
    if (set_.type == MeasurementType::laser && !set_.meta("line").empty()) {
      line_axis_ = set_.meta("axis")[0];
      const auto parts = split(set_.meta("line"), ',');
      const Context at_line{file_, key_line("line"), raw};
      for (int k = 0; k < 2; ++k) line_mm_[k] = number(parts[static_cast<std::size_t>(k)], at_line, "line");
    }
  }

  void read_type(const Context& where) {
    const std::string type = set_.meta("type");
    if (type.empty()) where.fail("missing '# type:' line before the header (ballbar, sphere or laser)");
    if (type == "ballbar")
      set_.type = MeasurementType::ballbar;
    else if (type == "sphere")
      set_.type = MeasurementType::sphere;
    else if (type == "laser")
      set_.type = MeasurementType::laser;
    else
      throw InputError({file_, key_line("type"), 0}, fmt::format("unknown type '{}' (ballbar, sphere or laser)", type));
  }

  /// Temperature, expansion, instrument, serial, operator and date (measurement_conditions.hpp),
  /// and a notice for each known key the file's type does not use.
  void read_conditions(const std::string& raw) {
    auto at_key = [&](const std::string& key) { return Context{file_, key_line(key), raw}; };
    MeasurementConditions& c = set_.conditions;
    if (const std::string t = set_.meta("temperature"); !t.empty()) {
      c.temperature_c = number(t, at_key("temperature"), "temperature");
      if (*c.temperature_c < kLowestTemperatureC || *c.temperature_c > kHighestTemperatureC)
        at_key("temperature")
            .fail(fmt::format("temperature {} °C is outside {:g}–{:g} °C, where no machine is measured: "
                              "degrees Celsius expected (°F or K?)",
                              t, kLowestTemperatureC, kHighestTemperatureC));
    }
    if (const std::string a = set_.meta("material_expansion"); !a.empty()) {
      c.expansion_per_k = number(a, at_key("material_expansion"), "material_expansion");
      if (std::abs(*c.expansion_per_k) > kLargestExpansionPerK)
        at_key("material_expansion")
            .fail(fmt::format("material_expansion {} is not a linear expansion coefficient in 1/K (steel 11.5e-6, cast "
                              "iron 10.5e-6, aluminium 23e-6; at most {:g}): write e.g. 11.5e-6 for 11.5 µm/(m·K)",
                              a, kLargestExpansionPerK));
      if (!c.temperature_c)
        at_key("material_expansion")
            .fail(
                "material_expansion without '# temperature:': the correction to 20 °C needs the machine's temperature "
                "(°C); give it or remove the coefficient");
    }
    if (const std::string d = set_.meta("date"); !d.empty()) {
      if (!is_iso8601_date(d))
        at_key("date").fail(
            fmt::format("date '{}' is not ISO 8601: expected e.g. 2026-11-20T09:30 (or 2026-11-20)", d));
      c.date = d;
    }
    c.instrument_U_um = positive_key("instrument_uncertainty", kLargestInstrumentUUm, "µm", raw);
    c.temperature_u_k = positive_key("temperature_uncertainty", kLargestTemperatureUK, "K", raw);
    c.expansion_u_per_k = positive_key("expansion_uncertainty", kLargestExpansionPerK, "1/K", raw);
    c.instrument = set_.meta("instrument");
    c.serial = set_.meta("serial");
    c.operator_name = set_.meta("operator");
    const std::string type = to_string(set_.type);
    for (std::size_t i = 0; i < set_.metadata.size(); ++i) {
      const HeaderKey* k = known_key(set_.metadata[i].first);
      if (k && std::string(k->types).find(type) == std::string::npos)
        set_.notices.push_back(fmt::format("{}:{}: '# {}:' is not used in a {} file (it is a {} key)", file_,
                                           meta_lines_[i], k->name, type, k->types));
    }
  }

  /// An uncertainty key: a number > 0 and at most `largest` (its unit), or absent.
  std::optional<double> positive_key(const std::string& key, double largest, const char* unit, const std::string& raw) {
    const std::string text = set_.meta(key);
    if (text.empty()) return std::nullopt;
    const Context at{file_, key_line(key), raw};
    const double v = number(text, at, key);
    if (!(v > 0.0) || v > largest)
      at.fail(
          fmt::format("{} {} is not an uncertainty in {} (greater than 0, at most {:g})", key, text, unit, largest));
    return v;
  }

  /// The keys of the type (table_ball, sphere, component, ...) and the tool length.
  void read_type_keys(const std::string& raw) {
    auto at_key = [&](const std::string& key) { return Context{file_, key_line(key), raw}; };
    switch (set_.type) {
      case MeasurementType::ballbar:
        set_.table_ball_mm = vector3(require("table_ball"), at_key("table_ball"), "table_ball");
        set_.tool_ball_mm = vector3(require("tool_ball"), at_key("tool_ball"), "tool_ball");
        set_.bar_length_mm = number(require("bar_length"), at_key("bar_length"), "bar_length");
        break;
      case MeasurementType::sphere:
        set_.sphere_mm = vector3(require("sphere"), at_key("sphere"), "sphere");
        break;
      case MeasurementType::laser:
        read_laser_keys(raw);
        break;
    }
    if (!set_.meta("tool_length").empty())
      set_.tool_length_mm = number(set_.meta("tool_length"), at_key("tool_length"), "tool_length");
  }

  void read_laser_keys(const std::string& raw) {
    auto at_key = [&](const std::string& key) { return Context{file_, key_line(key), raw}; };
    const std::string c = require("component");
    if (c.size() != 1 || (c[0] != 'X' && c[0] != 'Y' && c[0] != 'Z'))
      throw InputError({file_, key_line("component"), 0}, fmt::format("component must be X, Y or Z, found '{}'", c));
    set_.component = c[0];
    set_.tool_point_mm = vector3(require("tool_point"), at_key("tool_point"), "tool_point");
    const std::string moving = set_.meta("axis");
    if (!moving.empty() && (moving.size() != 1 || moving[0] < 'X' || moving[0] > 'Z'))
      throw InputError({file_, key_line("axis"), 0}, fmt::format("axis must be X, Y or Z, found '{}'", moving));
    if (!set_.meta("line").empty()) {
      if (moving.empty()) throw InputError({file_, key_line("line"), 0}, "'# line:' needs '# axis:' (the moving axis)");
      const auto parts = split(set_.meta("line"), ',');
      if (parts.size() != 2)
        throw InputError({file_, key_line("line"), 0},
                         "expected two comma-separated numbers (mm) for 'line': the other two axes, XYZ order");
      for (const auto& p : parts) number(p, at_key("line"), "line");
    }
    bool head = false;
    for (const auto& a : m_.axes) head = head || (a.is_rotary() && a.side == Side::tool);
    if (head) require("tool_length");
  }

  /// The columns of t, run, approach, every axis and the values (none in a plan, when allowed).
  void read_columns(const Context& where) {
    for (std::size_t c = 0; c < header_.size(); ++c) {
      const std::string& h = header_[c];
      if (h == "t")
        t_col_ = static_cast<int>(c);
      else if (h == "run")
        run_col_ = static_cast<int>(c);
      else if (h == "approach" && set_.type == MeasurementType::laser)
        approach_col_ = static_cast<int>(c);
      else if (h.size() == 1 && m_.index_of(h[0]) >= 0) {
        if (column_of_axis_[static_cast<std::size_t>(m_.index_of(h[0]))] >= 0)
          where.fail("column " + h + " given twice");
        column_of_axis_[static_cast<std::size_t>(m_.index_of(h[0]))] = static_cast<int>(c);
      }
    }
    if (t_col_ < 0) where.fail("missing column 't' (time, s)");
    if (set_.type == MeasurementType::laser && run_col_ < 0) where.fail("missing column 'run' of a laser file");
    for (std::size_t a = 0; a < m_.axes.size(); ++a) {
      const bool optional = set_.type == MeasurementType::laser && m_.axes[a].is_rotary();
      if (column_of_axis_[a] < 0 && !optional)
        where.fail(fmt::format("missing column {} (axis of machine '{}')", m_.axes[a].letter, m_.name));
    }
    int found = 0;
    for (const std::string& v : set_.value_columns()) {
      int col = -1;
      for (std::size_t c = 0; c < header_.size(); ++c)
        if (header_[c] == v) col = static_cast<int>(c);
      value_cols_.push_back(col);
      found += col >= 0;
    }
    if (found == 0 && options_.allow_plan) {
      set_.has_values = false;
    } else if (found != static_cast<int>(value_cols_.size())) {
      std::string names;
      for (const auto& v : set_.value_columns()) names += (names.empty() ? "" : ", ") + v;
      where.fail(fmt::format("missing value column(s) of a {} file: expected {}", to_string(set_.type), names));
    }
  }

  void read_row(const std::string& raw, const Context& where) {
    const auto fields = split(raw, ',');
    if (fields.size() != header_.size())
      where.fail(fmt::format("expected {} fields as in the header (line {}), found {}", header_.size(), header_line_,
                             fields.size()));
    MeasurementRow row;
    row.line = line_no_;
    row.time_s = number(fields[static_cast<std::size_t>(t_col_)], where, "t");
    if (!set_.rows.empty() && !(row.time_s > set_.rows.back().time_s))
      where.fail(fmt::format("time t = {} s is not after the previous row's t = {} s (line {}): rows must be in "
                             "recording order with increasing time stamps; sort the rows or correct the time column",
                             fields[static_cast<std::size_t>(t_col_)], set_.rows.back().time_s, set_.rows.back().line),
                 column_of_field(raw, static_cast<std::size_t>(t_col_)));
    for (std::size_t a = 0; a < m_.axes.size(); ++a) {
      if (column_of_axis_[a] < 0) continue;
      const double v =
          number(fields[static_cast<std::size_t>(column_of_axis_[a])], where, std::string(1, m_.axes[a].letter));
      row.command[static_cast<int>(a)] = m_.axes[a].is_rotary() ? deg_to_rad(v) : v;
    }
    if (run_col_ >= 0) {
      const double r = number(fields[static_cast<std::size_t>(run_col_)], where, "run");
      if (r != std::floor(r)) where.fail("run must be an integer");
      row.run = static_cast<int>(r);
    }
    if (approach_col_ >= 0) {
      const std::string& a = fields[static_cast<std::size_t>(approach_col_)];
      if (a == "1" || a == "+1")
        row.approach = 1;
      else if (a == "-1")
        row.approach = -1;
      else
        where.fail(fmt::format("approach must be +1 (from below) or -1 (from above), found '{}'", a));
    }
    if (line_axis_ != 0) check_on_line(row, where);
    if (set_.has_values) read_values(row, fields, raw, where);
    set_.rows.push_back(row);
  }

  /// A laser row's other two axes on the file's '# line:'.
  void check_on_line(const MeasurementRow& row, const Context& where) const {
    int k = 0;
    for (char other : {'X', 'Y', 'Z'}) {
      if (other == line_axis_) continue;
      const int ai = m_.index_of(other);
      if (ai >= 0 && std::abs(row.command[ai] - line_mm_[k]) > kOffLineMm)
        where.fail(fmt::format("{} = {} is off the line of the file header ('# line:' says {})", other, row.command[ai],
                               line_mm_[k]));
      ++k;
    }
  }

  /// The values of a row, each within what the instrument can read.
  void read_values(MeasurementRow& row, const std::vector<std::string>& fields, const std::string& raw,
                   const Context& where) const {
    for (std::size_t v = 0; v < value_cols_.size(); ++v) {
      const auto col = static_cast<std::size_t>(value_cols_[v]);
      const double value = number(fields[col], where, header_[col]);
      row.value[static_cast<Eigen::Index>(v)] = value;
      const ReadingRange& range = reading_range(set_.type);
      const double deviation = set_.type == MeasurementType::ballbar ? value - set_.bar_length_mm : value;
      if (!(std::abs(deviation) <= range.max_deviation))
        where.fail(fmt::format("{} = {} is {:g} {} from {}, beyond what the instrument can read (at most {:g} {}): a "
                               "typing or export error; correct or delete the row",
                               header_[col], fields[col], std::abs(deviation), range.unit,
                               set_.type == MeasurementType::ballbar ? "the bar length" : "zero", range.max_deviation,
                               range.unit),
                   column_of_field(raw, col));
    }
  }

  const std::string& file_;
  const Machine& m_;
  const CsvReadOptions& options_;
  MeasurementSet set_;
  int line_no_ = 0;
  std::vector<int> meta_lines_;
  std::vector<std::string> header_;
  int header_line_ = 0;
  std::vector<int> column_of_axis_;
  int t_col_ = -1, run_col_ = -1, approach_col_ = -1;
  char line_axis_ = 0;
  double line_mm_[2] = {0.0, 0.0};
  std::vector<int> value_cols_;
};

}  // namespace

MeasurementSet parse_measurement_csv(const std::string& text, const std::string& file_name, const Machine& m,
                                     const CsvReadOptions& options) {
  return CsvParser(file_name, m, options).parse(text);
}

MeasurementSet read_measurement_csv(const std::string& path, const Machine& m, const CsvReadOptions& options) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError({path, 0, 0}, "cannot open the file");
  std::ostringstream s;
  s << f.rdbuf();
  return parse_measurement_csv(s.str(), path, m, options);
}

std::string format_measurement_csv(const MeasurementSet& set, const Machine& m) {
  std::string out;
  out += fmt::format("# type: {}\n", to_string(set.type));
  auto known = [&](const std::string& key) {
    if (key == "type" || key == "tool_length") return true;
    switch (set.type) {
      case MeasurementType::ballbar:
        return key == "table_ball" || key == "tool_ball" || key == "bar_length";
      case MeasurementType::sphere:
        return key == "sphere";
      case MeasurementType::laser:
        return key == "component" || key == "tool_point";
    }
    return false;
  };
  switch (set.type) {
    case MeasurementType::ballbar:
      out += fmt::format("# table_ball: {:.4f}\n# tool_ball: {:.4f}\n# bar_length: {:.4f}\n", set.table_ball_mm,
                         set.tool_ball_mm, set.bar_length_mm);
      break;
    case MeasurementType::sphere:
      out += fmt::format("# sphere: {:.4f}\n", set.sphere_mm);
      break;
    case MeasurementType::laser:
      out += fmt::format("# component: {}\n# tool_point: {:.4f}\n", set.component, set.tool_point_mm);
      break;
  }
  if (set.tool_length_mm != 0.0 || set.type == MeasurementType::laser || !set.meta("tool_length").empty())
    out += fmt::format("# tool_length: {:.4f}\n", set.tool_length_mm);
  for (const auto& [k, v] : set.metadata)
    if (!known(k)) out += fmt::format("# {}: {}\n", k, v);
  bool approach = false;
  for (const auto& r : set.rows) approach = approach || r.approach != 0;
  out += "t";
  if (set.type == MeasurementType::laser) out += ",run";
  if (approach) out += ",approach";
  for (const auto& a : m.axes) out += fmt::format(",{}", a.letter);
  if (set.has_values)
    for (const auto& v : set.value_columns()) out += "," + v;
  out += "\n";
  for (const auto& r : set.rows) {
    out += fmt::format("{:.2f}", r.time_s);
    if (set.type == MeasurementType::laser) out += fmt::format(",{}", r.run);
    if (approach) out += r.approach < 0 ? ",-1" : ",+1";
    for (std::size_t a = 0; a < m.axes.size(); ++a) {
      const double v = r.command[static_cast<int>(a)];
      out += fmt::format(",{:.5f}", m.axes[a].is_rotary() ? rad_to_deg(v) : v);
    }
    if (set.has_values) {
      if (set.type == MeasurementType::laser)
        out += fmt::format(",{:.4f}", r.value[0]);
      else
        for (int v = 0; v < set.values_per_row(); ++v) out += fmt::format(",{:.6f}", r.value[v]);
    }
    out += "\n";
  }
  return out;
}

}  // namespace ncpost::comp
