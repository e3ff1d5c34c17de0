// SPDX-License-Identifier: Apache-2.0
#pragma once
// SHA-256 (FIPS 180-4) of bytes and of files, as lowercase hex: the reports name every input
// file with its hash so that a report can be matched with the data it was made from.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ncpost::report {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  void update(std::string_view text) { update(text.data(), text.size()); }
  /// The digest as 64 lowercase hex digits; the object is spent afterwards.
  std::string hex();

 private:
  void block(const std::uint8_t* p);
  std::uint32_t h_[8];
  std::uint8_t buffer_[64];
  std::size_t used_ = 0;
  std::uint64_t bytes_ = 0;
};

/// SHA-256 of `text` (hex).
std::string sha256_hex(std::string_view text);

/// SHA-256 of the file's bytes (hex), or nullopt if it cannot be read (e.g. standard input).
std::optional<std::string> file_sha256_hex(const std::string& path);

}  // namespace ncpost::report
