#include "ncpost/postproc/atomic_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace ncpost {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    to_stdout_ = true;
    file_ = stdout;
    return;
  }
  std::string pattern = path_ + ".tmp.XXXXXX";
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if (fd < 0) throw std::runtime_error("cannot create a temporary file beside '" + path_ + "': " + std::strerror(errno));
  temp_path_ = buf.data();
  // mkstemp creates 0600; give the file the mode an ordinary create would (0666 less the umask)
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  file_ = ::fdopen(fd, "w");
  if (!file_) {
    ::close(fd);
    ::unlink(temp_path_.c_str());
    throw std::runtime_error("cannot open '" + temp_path_ + "'");
  }
}

AtomicFile::~AtomicFile() {
  if (to_stdout_ || committed_) return;
  if (file_) std::fclose(file_);
  ::unlink(temp_path_.c_str());
}

void AtomicFile::write(std::string_view data) {
  if (std::fwrite(data.data(), 1, data.size(), file_) != data.size())
    throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(errno));
}

void AtomicFile::commit() {
  if (to_stdout_) {
    std::fflush(stdout);
    return;
  }
  if (std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0) throw std::runtime_error("cannot write '" + path_ + "'");
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (rc != 0) {
    ::unlink(temp_path_.c_str());
    throw std::runtime_error("cannot write '" + path_ + "'");
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    ::unlink(temp_path_.c_str());
    throw std::runtime_error("cannot rename into '" + path_ + "': " + std::strerror(errno));
  }
  committed_ = true;
}

void write_file_atomically(const std::string& path, std::string_view data) {
  AtomicFile f(path);
  f.write(data);
  f.commit();
}

}  // namespace ncpost
