// SPDX-License-Identifier: Apache-2.0
#pragma once
// The input of `post` and `preview`, which is read more than once (the kind is detected from its
// first bytes, --verify reads it a second time): a regular file is read where it is; standard
// input ("-") and pipes (/dev/stdin, <(...)) are first copied to a temporary file, removed when the
// run ends or is stopped by a signal.
#include <string>

namespace ncpost::cli {

class InputFile {
 public:
  /// `given`: the INPUT argument. FileError when it cannot be read.
  explicit InputFile(const std::string& given);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// The file to open (the spool for a pipe).
  const std::string& path() const { return path_; }
  /// The name in messages and reports ("<stdin>" for "-").
  const std::string& name() const { return name_; }

 private:
  std::string path_;
  std::string name_;
  bool spooled_ = false;
};

}  // namespace ncpost::cli

#include <CLI/CLI.hpp>

namespace ncpost::cli {

/// A CLI11 check for an INPUT argument: "-" (standard input) or a file that exists.
CLI::Validator existing_input();

}  // namespace ncpost::cli
