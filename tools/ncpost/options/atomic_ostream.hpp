// SPDX-License-Identifier: Apache-2.0
#pragma once
// An std::ostream over an AtomicFile (the output of `post`, written by the library entry point):
// every write goes straight to the file (no second buffer), a failed write rethrows the file's
// FileError (naming the path and the reason), and the file appears only on AtomicFile::commit().
#include <ostream>
#include <streambuf>

#include "ncpost/postproc/write/atomic_file.hpp"

namespace ncpost::cli {

class AtomicFileBuf final : public std::streambuf {
 public:
  explicit AtomicFileBuf(AtomicFile& file) : file_(file) {}

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    file_.write(std::string_view(s, static_cast<std::size_t>(n)));
    return n;
  }
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    file_.write(std::string_view(&ch, 1));
    return c;
  }

 private:
  AtomicFile& file_;
};

class AtomicOstream final : public std::ostream {
 public:
  explicit AtomicOstream(AtomicFile& file) : std::ostream(nullptr), buf_(file) {
    rdbuf(&buf_);
    exceptions(std::ios::badbit);  // the file's FileError reaches the caller as it is
  }

 private:
  AtomicFileBuf buf_;
};

}  // namespace ncpost::cli
