// SPDX-License-Identifier: Apache-2.0
// Work offsets placed in the base frame (see work_frames.hpp).
#include "ncpost/postproc/read/gcode/work_frames.hpp"

#include <fmt/format.h>

namespace ncpost::gcode {
namespace {
constexpr const char* kLetters = "XYZABC";
}

WorkFrames::WorkFrames(std::shared_ptr<const WorkOffsetTable> table, std::array<bool, 6> used)
    : table_(std::move(table)), used_(used) {
  if (!table_) return;
  for (const auto& [name, given] : table_->offsets) {
    Values& v = values_[name];
    for (std::size_t i = 0; i < 6; ++i)
      if (given[i]) v[i] = Value{*given[i], false};
    sources_[name] = table_->file;
  }
}

std::optional<double> WorkFrames::shift_of(const Values& values, std::size_t axis) const {
  const std::optional<Value>& v = values[axis];
  if (!v) return std::nullopt;
  if (v->from_base) return v->v;
  if (!base_value_[axis]) return std::nullopt;
  return v->v - *base_value_[axis];
}

std::string WorkFrames::named(const std::string& name) {
  return name.empty() ? std::string("the control's active offset") : name;
}

std::string WorkFrames::update_shift() {
  if (!fixed_) return {};
  const Values& values = values_[active_];
  std::string unknown;
  std::array<double, 6> shift{};
  for (std::size_t i = 0; i < 6; ++i) {
    if (!used_[i]) continue;
    const std::optional<double> s = shift_of(values, i);
    if (s)
      shift[i] = *s;
    else
      unknown += fmt::format("{}{}", unknown.empty() ? "" : ", ", kLetters[i]);
  }
  if (!unknown.empty()) {
    const std::string given = table_ ? fmt::format("the work offsets file {} does not give", table_->file)
                                     : std::string("no --work-offsets FILE gives");
    return fmt::format(
        "{}: a second work offset (the program moved in {}): where it lies relative to {} is not known "
        "({} {} of both, nor does a G10 L2 of the program): give both offsets' values with "
        "--work-offsets FILE (docs/formats.md \"Work offsets\"), or post the operations of each set-up "
        "apart",
        named(active_), named(base_), named(base_), given, unknown);
  }
  offset_shift_ = shift;
  combine();
  return {};
}

void WorkFrames::combine() {
  for (std::size_t i = 0; i < 6; ++i) shift_[i] = offset_shift_[i] + local_[i];
}

void WorkFrames::set_local(const std::array<std::optional<double>, 6>& shift) {
  for (std::size_t i = 0; i < 6; ++i)
    if (shift[i]) local_[i] = *shift[i];
  combine();
}

void WorkFrames::set_local_reading(const std::array<double, 6>& position_base,
                                   const std::array<std::optional<double>, 6>& reads) {
  for (std::size_t i = 0; i < 6; ++i)
    if (reads[i]) local_[i] = position_base[i] - *reads[i] - offset_shift_[i];
  combine();
}

std::string WorkFrames::select(const std::string& name) {
  active_ = name;
  return update_shift();
}

void WorkFrames::moved() {
  if (fixed_) return;
  fixed_ = true;
  base_ = active_;
  Values& values = values_[base_];
  for (std::size_t i = 0; i < 6; ++i) {
    if (values[i] && !values[i]->from_base)
      base_value_[i] = values[i]->v;
    else
      values[i] = Value{0.0, true};
  }
  offset_shift_ = {};
  combine();
}

std::string WorkFrames::set_value(const std::string& name, const std::array<std::optional<double>, 6>& machine_value) {
  Values& values = values_[name];
  for (std::size_t i = 0; i < 6; ++i)
    if (machine_value[i]) values[i] = Value{*machine_value[i], false};
  return name == active_ ? update_shift() : std::string();
}

std::string WorkFrames::set_reading(const std::string& name, const std::array<double, 6>& position_base,
                                    const std::array<std::optional<double>, 6>& reads) {
  Values& values = values_[name];
  for (std::size_t i = 0; i < 6; ++i)
    if (reads[i]) values[i] = Value{position_base[i] - *reads[i], true};
  return name == active_ ? update_shift() : std::string();
}

std::string WorkFrames::source_of(const std::string& name) const {
  const auto it = sources_.find(name);
  return it == sources_.end() ? std::string("the program") : it->second;
}

}  // namespace ncpost::gcode
