#include "ncpost/postproc/dialect.hpp"

#include <stdexcept>

namespace ncpost {

Dialect dialect_named(const std::string& name) {
  Dialect d;
  d.name = name;
  if (name == "fanuc") {
    d.rtcp_on = "G43.4 H1";
    d.rtcp_off = "G49";
  } else if (name == "haas") {
    d.rtcp_on = "G234 H1";
    d.rtcp_off = "G49";
  } else if (name == "linuxcnc") {
    d.percent_framing = false;
    d.rtcp_on = "M428";
    d.rtcp_off = "M429";
    d.program_end = "M2";
  } else if (name == "sinumerik") {
    d.comments = Dialect::Comments::semicolon;
    d.percent_framing = false;
    d.rtcp_on = "TRAORI";
    d.rtcp_off = "TRAFOOF";
  } else if (name == "heidenhain") {
    d.comments = Dialect::Comments::semicolon;
    d.percent_framing = false;
    d.klartext = true;
    d.line_numbers = true;
    d.rtcp_on = "M128";
    d.rtcp_off = "M129";
    d.program_end = "M30";
    d.linear_decimals = 4;
  } else {
    throw std::invalid_argument("unknown dialect '" + name + "' (expected fanuc, haas, linuxcnc, sinumerik or heidenhain)");
  }
  return d;
}

}  // namespace ncpost
