// SPDX-License-Identifier: Apache-2.0
// Recognizing a Sinumerik program by its head (sinumerik_reader.hpp).
#include <cctype>
#include <regex>
#include <string>

#include "ncpost/postproc/read/sinumerik/sinumerik_reader.hpp"

namespace ncpost::sinumerik {

bool looks_like_sinumerik(std::string_view head) {
  static const std::regex kMarks(
      R"(^\s*%_N_\w+_(MPF|SPF)\b)"
      R"(|^\s*(N\d+\s+)?(DEF\s+(REAL|INT|BOOL|STRING)\b|PROC\s+\w|MCALL\b|TRANS\s|ATRANS\s|AROT\s|ROT\s+[XYZ]))"
      R"(|\b(CYCLE8\d\d?\s*\(|GOTO[FB]\s|SUPA\b|T\s*=\s*"))"
      R"(|(^|\s)(R\d+|[XYZIJK]|[ABC]3|CR|_\w+)\s*=\s*[-+(.\w"])",
      std::regex::icase | std::regex::optimize);
  std::size_t from = 0;
  while (from < head.size()) {
    std::size_t to = head.find('\n', from);
    if (to == std::string_view::npos) to = head.size();
    std::string line(head.substr(from, to - from));
    from = to + 1;
    const std::size_t semi = line.find(';');
    if (semi != std::string::npos) line.erase(semi);
    const std::size_t paren = line.find('(');
    if (paren != std::string::npos && line.find("CYCLE") == std::string::npos &&
        line.find("cycle") == std::string::npos)
      line.erase(paren);  // an ISO (comment)
    if (std::regex_search(line, kMarks)) return true;
  }
  return false;
}

}  // namespace ncpost::sinumerik
