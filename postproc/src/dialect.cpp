// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/dialect.hpp"

#include <stdexcept>

namespace ncpost {

Dialect dialect_named(const std::string& name) {
  Dialect d;
  d.name = name;
  if (name == "fanuc") {
    d.tool_length_on = {"G43 H{tool}"};
    d.rtcp_on = {"G43.4 H{tool}"};
    d.rtcp_off = {"G49"};
  } else if (name == "haas") {
    d.tool_length_on = {"G43 H{tool}"};
    d.rtcp_on = {"G234 H{tool}"};
    d.rtcp_off = {"G49"};
  } else if (name == "linuxcnc") {
    d.percent_framing = false;
    d.tool_length_on = {"G43"};  // the loaded tool's length
    d.rtcp_on = {"G43 H{tool}", "M428"};  // switchkins: tool-length offset, then TCP kinematics
    d.rtcp_off = {"M429", "G49"};
    d.program_end = "M2";
  } else if (name == "sinumerik") {
    d.comments = Dialect::Comments::semicolon;
    d.percent_framing = false;
    d.tool_call = {"T{tool} M6 D1"};  // D1: the tool's first cutting edge, its length
    d.rtcp_on = {"TRAORI"};
    d.rtcp_off = {"TRAFOOF"};
  } else if (name == "heidenhain") {
    d.comments = Dialect::Comments::semicolon;
    d.percent_framing = false;
    d.klartext = true;
    d.line_numbers = true;
    d.tool_call = {"TOOL CALL {tool} Z"};  // activates the tool's length
    d.rtcp_on = {"M128"};
    d.rtcp_off = {"M129"};
    d.program_end = "M30";
    d.linear_decimals = 4;
  } else {
    throw std::invalid_argument("unknown dialect '" + name + "' (expected fanuc, haas, linuxcnc, sinumerik or heidenhain)");
  }
  return d;
}

std::string with_tool(const std::string& words, int tool) {
  static const std::string kPlaceholder = "{tool}";
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = words.find(kPlaceholder, from)) != std::string::npos; from = at + kPlaceholder.size())
    out.append(words, from, at - from).append(std::to_string(tool));
  return out.append(words, from, std::string::npos);
}

}  // namespace ncpost
