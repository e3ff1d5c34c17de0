// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/read/line_source.hpp"

#include <fmt/format.h>

#include <cstring>

#include "ncpost/machines/input_error.hpp"

namespace ncpost {

std::string echo_of(std::string_view line, std::size_t max_bytes) {
  if (line.size() <= max_bytes) return std::string(line);
  return std::string(line.substr(0, max_bytes)) + "...";
}

std::string echo_for(std::string_view line, int column) {
  if (column > static_cast<int>(LineSource::kEchoBytes)) return {};
  return echo_of(line);
}

LineSource::LineSource(std::istream& in, std::string file_name, std::string expected)
    : in_(&in),
      origin_(in.tellg()),
      file_(std::move(file_name)),
      expected_(std::move(expected)),
      buffer_(kChunkBytes) {}

bool LineSource::seek(std::uint64_t offset, int line_number) {
  if (origin_ == std::istream::pos_type(-1)) return false;
  in_->clear();
  in_->seekg(origin_ + static_cast<std::streamoff>(offset));
  if (!*in_) return false;
  begin_ = end_ = 0;
  eof_ = false;
  bom_checked_ = offset != 0;  // a byte order mark stands only at offset 0
  terminated_ = true;
  bytes_read_ = offset;
  line_number_ = line_number - 1;
  return true;
}

void LineSource::switch_input(std::istream& in, std::istream::pos_type origin, std::string file_name) {
  in_ = &in;
  origin_ = origin;
  file_ = std::move(file_name);
  begin_ = end_ = 0;
  eof_ = false;
}

bool LineSource::refill() {
  if (eof_) return false;
  if (begin_ > 0) {  // keep the unread tail at the front, then append a chunk
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ > kMaxLineBytes) {
    const std::string_view head(buffer_.data(), kEchoBytes);
    throw InputError(
        {file_, line_number_ + 1, 1},
        fmt::format("line too long (more than {} MiB without a line break: binary data or a damaged file?); "
                    "expected {}",
                    kMaxLineBytes >> 20, expected_),
        echo_of(head, kEchoBytes - 1));
  }
  if (buffer_.size() - end_ < kChunkBytes) buffer_.resize(end_ + kChunkBytes);
  in_->read(buffer_.data() + end_, static_cast<std::streamsize>(buffer_.size() - end_));
  const auto got = static_cast<std::size_t>(in_->gcount());
  if (in_->bad()) throw InputError({file_, line_number_ + 1, 0}, "read error");
  end_ += got;
  bytes_read_ += got;
  if (got == 0 || in_->eof()) eof_ = true;
  if (!bom_checked_ && (end_ >= 3 || eof_)) {
    bom_checked_ = true;
    if (end_ - begin_ >= 3 && std::memcmp(buffer_.data() + begin_, "\xEF\xBB\xBF", 3) == 0) begin_ += 3;
  }
  return got > 0;
}

std::string_view LineSource::peek(std::size_t bytes) {
  if (!bom_checked_) refill();
  while (end_ - begin_ < bytes && refill()) {
  }
  return std::string_view(buffer_.data() + begin_, end_ - begin_);
}

bool LineSource::next(std::string_view& line) {
  if (!bom_checked_) refill();
  for (;;) {
    const char* data = buffer_.data();
    const std::size_t n = end_ - begin_;
    std::size_t pos = n;
    if (const void* lf = std::memchr(data + begin_, '\n', n))
      pos = static_cast<std::size_t>(static_cast<const char*>(lf) - (data + begin_));
    if (const void* cr = std::memchr(data + begin_, '\r', pos))
      pos = static_cast<std::size_t>(static_cast<const char*>(cr) - (data + begin_));
    // a CR at the very end of the data may be the first half of a CRLF: read on before deciding
    const bool complete = pos < n && !(data[begin_ + pos] == '\r' && pos + 1 == n && !eof_);
    if (complete || (pos == n && eof_)) {
      if (pos == n && n == 0) return false;
      line = std::string_view(data + begin_, pos);
      std::size_t consumed = pos;
      terminated_ = pos < n;
      if (pos < n) {
        consumed += (data[begin_ + pos] == '\r' && pos + 1 < n && data[begin_ + pos + 1] == '\n') ? 2 : 1;
      }
      begin_ += consumed;
      ++line_number_;
      return true;
    }
    if (!refill() && !eof_) return false;
  }
}

}  // namespace ncpost
