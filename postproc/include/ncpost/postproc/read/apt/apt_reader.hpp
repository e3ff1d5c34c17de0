// SPDX-License-Identifier: Apache-2.0
#pragma once
// Streaming reader of APT CL source as CAM systems write it (NX CLSF, CATIA APT, Creo
// Pro/CLfile): docs/formats.md "CL data" and tests/data/real/SOURCES.md.
//
// One statement at a time (memory stays flat in the file size). `$` at the end of a line
// continues the statement on the next line, possibly inside a number (`0$` / `.000000`);
// `$$` starts a comment. Lengths are converted to mm (UNITS/INCHES or the default units),
// feeds to mm/min (or mm/rev). Frames: NX's MSYS and Creo's CSYS are information for the post,
// not transforms (NX's own posts keep the GOTO coordinates); they pass through as comments.
#include <istream>
#include <memory>
#include <string>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::cl {

/// One statement with its arguments, as parsed (before its meaning is applied).
struct AptStatement {
  Location where;
  std::string major;  ///< upper case, inner spaces kept ("TOOL PATH", "END-OF-PATH")
  bool has_slash = false;
  std::string raw_arguments;  ///< the text after '/', trimmed
  struct Argument {
    bool is_number = false;
    double number = 0.0;
    std::string word;  ///< upper case
    int column = 0;    ///< 1-based column of the argument in its line (approximate across continuations)
  };
  std::vector<Argument> arguments;
};

/// Parses one logical statement (continuations already joined). Throws InputError.
AptStatement parse_apt_statement(const std::string& text, const std::string& file, Location where);

class AptReader final : public Reader {
 public:
  AptReader(std::istream& in, std::string file_name, ReaderOptions options = {});
  ~AptReader() override;
  std::optional<Record> next() override;
  std::vector<std::string> take_notices() override;
  std::string failure_hint() const override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// True if the text looks like APT CL data rather than G-code (first statements decide).
bool looks_like_apt(const std::string& head);

}  // namespace ncpost::cl
