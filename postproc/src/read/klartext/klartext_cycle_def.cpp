// SPDX-License-Identifier: Apache-2.0
#include "read/klartext/klartext_cycle_def.hpp"

#include <cctype>

namespace ncpost::klartext {

CycleDef cycle_def_of(const Block& b, const std::string& file, int line_number) {
  CycleDef c;
  const std::string& t = b.text;
  std::size_t p = 0;
  while (p < t.size() && std::isdigit(static_cast<unsigned char>(t[p]))) ++p;
  if (p == 0) return c;
  c.number = std::stoi(t.substr(0, p));
  std::size_t dot = p;
  while (dot < t.size() && t[dot] == ' ') ++dot;  // "9 .0": a blank before the part (hyperMILL for DMG)
  if (dot + 1 < t.size() && t[dot] == '.' && std::isdigit(static_cast<unsigned char>(t[dot + 1]))) {
    c.part = t[dot + 1] - '0';
    p = dot + 2;
  }
  c.rest = t.substr(p);
  // tokenize the rest as the words of an L block, then put the columns where they are in the line
  try {
    const Block words = parse_block("L " + c.rest, file, line_number);
    const int text_column = b.column + static_cast<int>(std::string("CYCL DEF ").size());
    for (Word w : words.words) {
      w.column += text_column + static_cast<int>(p) - 3;
      c.words.push_back(std::move(w));
    }
  } catch (const InputError&) {
    c.words.clear();  // (a header such as "DATUM SHIFT" or "BOHREN ~": no words to act on)
  }
  return c;
}

}  // namespace ncpost::klartext
