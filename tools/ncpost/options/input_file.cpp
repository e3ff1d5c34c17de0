// SPDX-License-Identifier: Apache-2.0
#include "input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "ncpost/postproc/write/temp_files.hpp"

namespace ncpost::cli {
namespace {

std::string temp_folder() {
  const char* t = std::getenv("TMPDIR");
  return t && *t ? t : "/tmp";
}

}  // namespace

InputFile::InputFile(const std::string& given) : path_(given), name_(given == "-" ? "<stdin>" : given) {
  int from = -1;
  if (given == "-") {
    from = STDIN_FILENO;
  } else {
    struct stat st {};
    if (::stat(given.c_str(), &st) != 0) throw FileError("cannot read '" + given + "': " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw FileError("cannot read '" + given + "': it is a folder, give a file");
    if (S_ISREG(st.st_mode)) return;  // read in place
    from = ::open(given.c_str(), O_RDONLY | O_CLOEXEC);
    if (from < 0) throw FileError("cannot read '" + given + "': " + std::strerror(errno));
  }
  std::string pattern = temp_folder() + "/ncpost-input.XXXXXX";
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int to = ::mkstemp(buf.data());
  if (to < 0) {
    const std::string why = std::strerror(errno);
    if (from != STDIN_FILENO) ::close(from);
    throw FileError("cannot copy '" + name_ + "' to a temporary file in '" + temp_folder() + "': " + why);
  }
  path_ = buf.data();
  spooled_ = true;
  remember_temp_file(path_);
  std::vector<char> chunk(1 << 16);
  std::string failure;
  for (;;) {
    const ssize_t n = ::read(from, chunk.data(), chunk.size());
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      failure = "cannot read '" + name_ + "': " + std::strerror(errno);
      break;
    }
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(to, chunk.data() + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        failure = "cannot copy '" + name_ + "' to '" + path_ + "': " + std::strerror(errno);
        break;
      }
      done += w;
    }
    if (!failure.empty()) break;
  }
  if (from != STDIN_FILENO) ::close(from);
  ::close(to);
  if (!failure.empty()) {
    ::unlink(path_.c_str());
    forget_temp_file(path_);
    throw FileError(failure);
  }
}

InputFile::~InputFile() {
  if (!spooled_) return;
  ::unlink(path_.c_str());
  forget_temp_file(path_);
}

}  // namespace ncpost::cli

namespace ncpost::cli {

CLI::Validator existing_input() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        if (path == "-") return {};
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0) return "cannot read '" + path + "': " + std::strerror(errno);
        if (S_ISDIR(st.st_mode)) return "'" + path + "' is a folder, expected a file";
        return {};
      },
      "FILE or - (standard input)");
}

}  // namespace ncpost::cli
