// SPDX-License-Identifier: Apache-2.0
#pragma once
// Physical lines of an APT CL file, read in fixed-size chunks so that memory stays bounded
// however long the file or a line: LF, CRLF and CR-only line ends all end a line; a UTF-8 byte
// order mark at the start of the file is skipped (columns of line 1 count after it). A line
// longer than kMaxLineBytes is bad input ("line too long"): the error echoes at most
// kEchoBytes of it, never the whole line.
#include <cstddef>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace ncpost::cl {

class AptLineSource {
 public:
  static constexpr std::size_t kChunkBytes = 1 << 16;
  static constexpr std::size_t kMaxLineBytes = 1 << 20;
  static constexpr std::size_t kEchoBytes = 200;

  AptLineSource(std::istream& in, std::string file_name);

  /// The next line without its terminator, valid until the next call; false at the end of the
  /// input. Throws InputError on a read failure or a line longer than kMaxLineBytes.
  bool next(std::string_view& line);

  int line_number() const { return line_number_; }  ///< 1-based number of the last line returned
  std::size_t bytes_read() const { return bytes_read_; }

 private:
  bool refill();

  std::istream& in_;
  std::string file_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;  ///< start of the unread data in buffer_
  std::size_t end_ = 0;    ///< end of the valid data in buffer_
  bool eof_ = false;
  bool bom_checked_ = false;
  int line_number_ = 0;
  std::size_t bytes_read_ = 0;
};

/// At most `max_bytes` of `line` for an error message, with "..." when cut.
std::string echo_of(std::string_view line, std::size_t max_bytes = AptLineSource::kEchoBytes);
/// The line to echo under an error at 1-based `column` (a caret goes under it): the line cut to
/// kEchoBytes, or "" (no echo) when the column lies beyond what would be shown.
std::string echo_for(std::string_view line, int column);

}  // namespace ncpost::cl
