// SPDX-License-Identifier: Apache-2.0
#pragma once
// fmt::formatter for the geometry and source types, so that call sites write `{:.4f}` of a point
// instead of spelling its coordinates:
//   Vec3d           "x, y, z", each coordinate with the format spec given ("{:.3f}" -> "1.000, 2.000, 3.000")
//   AxisPosition    its commands in slot order (X Y Z, then the further axes), as stored (mm, rad),
//                   each with the spec given, separated by ", "
//   SourcePosition  "file:line:column" (line and column left out where unknown, 0), as InputError writes it
// Here, not in kinematics/, because kinematics does not depend on fmt.
#include <fmt/format.h>

#include <array>
#include <string_view>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost::detail {

/// The format spec of a value ("{:.4f}": ".4f") kept to format each component with it.
class ComponentFormatter {
 public:
  constexpr auto parse(fmt::format_parse_context& ctx) -> decltype(ctx.begin()) {
    auto it = ctx.begin();
    for (; it != ctx.end() && *it != '}'; ++it) {
      if (length_ + 3 >= spec_.size()) throw fmt::format_error("ncpost: format spec too long");
      spec_[length_++] = *it;
    }
    return it;
  }

 protected:
  template <class It>
  It write(It out, double v, bool first) const {
    if (!first) out = fmt::format_to(out, ", ");
    std::array<char, 40> text{};
    std::size_t n = 0;
    text[n++] = '{';
    text[n++] = ':';
    for (std::size_t i = 0; i < length_; ++i) text[n++] = spec_[i];
    text[n++] = '}';
    return fmt::format_to(out, fmt::runtime(std::string_view(text.data(), n)), v);
  }

 private:
  std::array<char, 36> spec_{};
  std::size_t length_ = 0;
};

}  // namespace ncpost::detail

template <>
struct fmt::formatter<ncpost::Vec3d> : ncpost::detail::ComponentFormatter {
  template <class Context>
  auto format(const ncpost::Vec3d& v, Context& ctx) const {
    auto out = ctx.out();
    for (int i = 0; i < 3; ++i) out = write(out, v[i], i == 0);
    return out;
  }
};

template <>
struct fmt::formatter<ncpost::AxisPosition> : ncpost::detail::ComponentFormatter {
  template <class Context>
  auto format(const ncpost::AxisPosition& q, Context& ctx) const {
    auto out = ctx.out();
    for (int i = 0; i < q.size(); ++i) out = write(out, q[i], i == 0);
    return out;
  }
};

template <>
struct fmt::formatter<ncpost::SourcePosition> {
  constexpr auto parse(fmt::format_parse_context& ctx) -> decltype(ctx.begin()) { return ctx.begin(); }
  template <class Context>
  auto format(const ncpost::SourcePosition& p, Context& ctx) const {
    auto out = fmt::format_to(ctx.out(), "{}", p.file);
    if (p.line > 0) out = fmt::format_to(out, ":{}", p.line);
    if (p.column > 0) out = fmt::format_to(out, ":{}", p.column);
    return out;
  }
};
