// SPDX-License-Identifier: Apache-2.0
#pragma once
// Physical lines of a text input (an APT CL file, an NC program), read in fixed-size chunks so
// that memory stays bounded however long the file or a line. LF, CRLF and CR-only line ends all
// end a line; a UTF-8 byte order mark at the start of the input is skipped (columns of line 1
// count after it). A line longer than kMaxLineBytes is bad input ("line too long"): the error
// echoes at most kEchoBytes of it, never the whole line.
#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace ncpost {

class LineSource {
 public:
  static constexpr std::size_t kChunkBytes = 1 << 16;
  static constexpr std::size_t kMaxLineBytes = 1 << 20;
  static constexpr std::size_t kEchoBytes = 200;

  /// `expected` says what a line of this input is, for the "line too long" message (e.g. "APT
  /// CL statements, one per line").
  LineSource(std::istream& in, std::string file_name, std::string expected);

  /// The next line without its terminator, valid until the next call; false at the end of the
  /// input. Throws InputError on a read failure or a line longer than kMaxLineBytes.
  bool next(std::string_view& line);

  /// The input not yet returned, after reading ahead to at least `bytes` where the input has
  /// them (a look at the head of the file); valid until the next call of next().
  std::string_view peek(std::size_t bytes);

  /// Where the next line starts: bytes from where the input started (for seek()).
  std::uint64_t next_line_offset() const { return bytes_read_ - (end_ - begin_); }
  /// Reads on from `offset` (a next_line_offset()), numbering the next line `line_number`; false
  /// when the stream cannot be positioned (a pipe).
  bool seek(std::uint64_t offset, int line_number);

  /// Reads on from another input (a subprogram in another file): `in`, which started at `origin`,
  /// named `file_name` in messages from now on; seek() then says where. `in` must outlive the reading.
  void switch_input(std::istream& in, std::istream::pos_type origin, std::string file_name);
  std::istream& input() const { return *in_; }
  std::istream::pos_type origin() const { return origin_; }  ///< where the input started (-1: not seekable)

  int line_number() const { return line_number_; }  ///< 1-based number of the last line returned
  const std::string& file() const { return file_; }
  bool last_line_terminated() const { return terminated_; }  ///< the last line ended with a line break
  std::size_t bytes_read() const { return bytes_read_; }

 private:
  bool refill();

  std::istream* in_;
  std::istream::pos_type origin_;  ///< where the input started in the stream (-1: not seekable)
  std::string file_;
  std::string expected_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;  ///< start of the unread data in buffer_
  std::size_t end_ = 0;    ///< end of the valid data in buffer_
  bool eof_ = false;
  bool bom_checked_ = false;
  bool terminated_ = true;
  int line_number_ = 0;
  std::size_t bytes_read_ = 0;
};

/// At most `max_bytes` of `line` for an error message, with "..." when cut.
std::string echo_of(std::string_view line, std::size_t max_bytes = LineSource::kEchoBytes);
/// The line to echo under an error at 1-based `column` (a caret goes under it): the line cut to
/// kEchoBytes, or "" (no echo) when the column lies beyond what would be shown.
std::string echo_for(std::string_view line, int column);

}  // namespace ncpost
