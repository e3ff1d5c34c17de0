// SPDX-License-Identifier: Apache-2.0
#pragma once
// Streaming line reader for NC programs: reads the input in fixed-size chunks and hands out one
// line at a time (without its terminator: LF, CRLF), so that memory stays flat however long the
// file. A UTF-8 byte order mark at the start is dropped (columns of line 1 then count after it). A line longer than `max_line_bytes` is bad input (binary data or a missing newline).
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace ncpost::gcode {

class LineSource {
 public:
  static constexpr std::size_t kChunkBytes = 1 << 16;
  static constexpr std::size_t kMaxLineBytes = 1 << 20;

  LineSource(std::istream& in, std::string file_name);

  /// The next line, valid until the next call; false at the end of the input. Throws InputError
  /// on a read failure or an over-long line.
  bool next(std::string_view& line);

  /// The input not yet returned, after reading ahead to at least `bytes` where the input has
  /// them (a look at the head of the file); valid until the next call of next().
  std::string_view peek(std::size_t bytes);

  int line_number() const { return line_number_; }  ///< 1-based number of the last line returned
  const std::string& file() const { return file_; }
  bool last_line_terminated() const { return terminated_; }  ///< the last line ended with a newline
  std::size_t bytes_read() const { return bytes_read_; }

 private:
  bool refill();
  void strip_bom(std::string_view& line) const;

  std::istream& in_;
  std::string file_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;  ///< start of the unread data in buffer_
  std::size_t end_ = 0;    ///< end of the valid data in buffer_
  bool eof_ = false;
  bool terminated_ = true;
  int line_number_ = 0;
  std::size_t bytes_read_ = 0;
};

}  // namespace ncpost::gcode
