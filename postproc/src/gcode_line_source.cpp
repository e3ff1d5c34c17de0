// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/gcode_line_source.hpp"

#include <cstring>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::gcode {

LineSource::LineSource(std::istream& in, std::string file_name)
    : in_(in), file_(std::move(file_name)), buffer_(kChunkBytes) {}

bool LineSource::refill() {
  if (eof_) return false;
  // keep the unread tail, then append a chunk
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (buffer_.size() - end_ < kChunkBytes) {
    if (buffer_.size() >= kMaxLineBytes + kChunkBytes)
      throw InputError({file_, line_number_ + 1, 1},
                       "line longer than 1 MiB (binary data or missing line breaks?); expected a line of G-code");
    buffer_.resize(buffer_.size() + kChunkBytes);
  }
  in_.read(buffer_.data() + end_, static_cast<std::streamsize>(buffer_.size() - end_));
  const auto got = static_cast<std::size_t>(in_.gcount());
  if (in_.bad()) throw InputError({file_, line_number_ + 1, 0}, "read error");
  end_ += got;
  bytes_read_ += got;
  if (got == 0 || in_.eof()) eof_ = true;
  return got > 0;
}

std::string_view LineSource::peek(std::size_t bytes) {
  while (end_ - begin_ < bytes && refill()) {
  }
  return std::string_view(buffer_.data() + begin_, end_ - begin_);
}

void LineSource::strip_bom(std::string_view& line) const {
  if (line_number_ == 1 && line.size() >= 3 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
}

bool LineSource::next(std::string_view& line) {
  for (;;) {
    const char* data = buffer_.data();
    const void* nl = std::memchr(data + begin_, '\n', end_ - begin_);
    if (nl != nullptr) {
      const auto pos = static_cast<std::size_t>(static_cast<const char*>(nl) - data);
      std::size_t len = pos - begin_;
      if (len > 0 && data[begin_ + len - 1] == '\r') --len;
      line = std::string_view(data + begin_, len);
      begin_ = pos + 1;
      ++line_number_;
      terminated_ = true;
      strip_bom(line);
      return true;
    }
    if (!refill()) {
      if (begin_ == end_) return false;
      // the last line has no newline
      data = buffer_.data();
      std::size_t len = end_ - begin_;
      if (data[begin_ + len - 1] == '\r') --len;
      line = std::string_view(data + begin_, len);
      begin_ = end_;
      ++line_number_;
      terminated_ = false;
      strip_bom(line);
      return true;
    }
  }
}

}  // namespace ncpost::gcode
