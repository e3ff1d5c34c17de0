// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the Macro B / RS274NGC expression evaluator alone (gcode::Evaluator).
// Each input line but the last is an assignment `#ref = expression` into the parameters; the last
// line is evaluated as an expression. Bad input must end in ExpressionError with an offset inside
// the line; a value must be vacant or finite, and word_number must write it without an exponent,
// "inf" or "nan". Anything else (crash, other exception, sanitizer report, hang) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"

namespace {

void check_value(const ncpost::gcode::ParamValue& v) {
  if (!v) return;
  if (!std::isfinite(*v)) __builtin_trap();
  const std::string written = ncpost::gcode::word_number(*v);
  if (written.find_first_not_of("-.0123456789") != std::string::npos) __builtin_trap();
}

void check_offset(const ncpost::gcode::ExpressionError& e, std::string_view line) {
  if (e.offset() > line.size()) __builtin_trap();
}

/// `#ref = expression`: sets the parameter, as a macro assignment does.
void assign(std::string_view line, ncpost::gcode::Parameters& params) {
  ncpost::gcode::Evaluator eval(params);
  std::size_t at = line.find('#');
  if (at == std::string_view::npos) return;
  const ncpost::gcode::ParamRef ref = eval.reference(line, at);
  while (at < line.size() && (line[at] == ' ' || line[at] == '=')) ++at;
  const ncpost::gcode::ParamValue v = eval.expression(line, at);
  check_value(v);
  if (ref.name.empty()) {
    if (ref.number > 0) params.set(ref.number, v);
  } else {
    params.set(ref.name, v);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ncpost::gcode::Parameters params;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    const bool last = end == std::string_view::npos;
    if (last) end = text.size();
    const std::string_view line = text.substr(begin, end - begin);
    try {
      if (last) {
        ncpost::gcode::Evaluator eval(params);
        std::size_t at = 0;
        check_value(eval.expression(line, at));
        if (at > line.size()) __builtin_trap();
      } else {
        assign(line, params);
      }
    } catch (const ncpost::gcode::ExpressionError& e) {
      check_offset(e, line);
    }
    begin = end + 1;
  }
  return 0;
}
