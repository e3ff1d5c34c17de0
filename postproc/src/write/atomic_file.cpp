// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ostream>
#include <vector>

#include "ncpost/postproc/write/temp_files.hpp"

namespace ncpost {
namespace {

std::string reason() { return std::strerror(errno); }

std::string folder_of(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

/// The file a path names after following its symbolic links (the link stays, its target is
/// replaced). A dangling link names its target, which will be created.
std::string link_target(const std::string& path) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::vector<char> buf(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4095) + 1);
    const ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size());
    if (n < 0) throw FileError("'" + path + "': cannot read the symbolic link: " + reason());
    std::string target(buf.data(), static_cast<std::size_t>(n));
    p = !target.empty() && target[0] == '/' ? target : folder_of(p) + "/" + target;
  }
  throw FileError("'" + path + "': too many levels of symbolic links");
}

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    to_stdout_ = true;
    file_ = stdout;
    return;
  }
  if (path_.empty()) throw FileError("an output file name is empty");
  target_ = link_target(path_);
  // only regular files are written: a device, FIFO or socket at the path is refused before
  // anything is opened (opening a FIFO would wait for a reader)
  struct stat st {};
  bool exists = false;
  if (::stat(target_.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode)) throw FileError(fmt_refusal(st.st_mode));
    exists = true;
  } else if (errno != ENOENT) {
    throw FileError("cannot write '" + path_ + "': " + reason());
  }
  std::string pattern = target_ + ".tmp.XXXXXX";
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if (fd < 0) {
    const std::string why = reason();
    struct stat dir {};
    const std::string folder = folder_of(target_);
    if (::stat(folder.c_str(), &dir) != 0)
      throw FileError("cannot write '" + path_ + "': the folder '" + folder + "' does not exist (" + reason() + ")");
    throw FileError("cannot write '" + path_ + "': cannot create a file in '" + folder + "': " + why);
  }
  temp_path_ = buf.data();
  remember_temp_file(temp_path_);
  if (exists) {
    // the replaced file keeps its mode (and, where permitted, its owner)
    ::fchmod(fd, st.st_mode & 07777);
    if (::fchown(fd, st.st_uid, st.st_gid) != 0) { /* not permitted: the file becomes the writer's */
    }
  } else {
    // mkstemp creates 0600; give the file the mode an ordinary create would (0666 less the umask)
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
  file_ = ::fdopen(fd, "w");
  if (!file_) {
    ::close(fd);
    discard();
    throw FileError("cannot open '" + temp_path_ + "': " + reason());
  }
}

std::string AtomicFile::fmt_refusal(unsigned mode) const {
  std::string s = "cannot write '" + path_ + "'";
  if (target_ != path_) s += " (a link to '" + target_ + "')";
  return s + ": it is " + kind_of(static_cast<mode_t>(mode)) + "; ncpost writes only regular files, give a file name";
}

void AtomicFile::discard() {
  ::unlink(temp_path_.c_str());
  forget_temp_file(temp_path_);
}

AtomicFile::AtomicFile(std::ostream& sink) : path_("<stream>"), sink_(&sink) {}

AtomicFile::~AtomicFile() {
  if (sink_ || to_stdout_ || committed_) return;
  if (file_) std::fclose(file_);
  discard();
}

void AtomicFile::write(std::string_view data) {
  if (sink_) {
    if (!sink_->write(data.data(), static_cast<std::streamsize>(data.size())))
      throw FileError("cannot write the program: the output stream failed");
    return;
  }
  if (std::fwrite(data.data(), 1, data.size(), file_) != data.size()) {
    if (to_stdout_) throw FileError("cannot write to standard output: " + reason());
    throw FileError("cannot write '" + path_ + "': " + reason());
  }
}

void AtomicFile::commit() {
  if (sink_) {
    if (!sink_->flush()) throw FileError("cannot write the program: the output stream failed");
    return;
  }
  if (to_stdout_) {
    if (std::fflush(stdout) != 0) throw FileError("cannot write to standard output: " + reason());
    return;
  }
  if (std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0)
    throw FileError("cannot write '" + path_ + "': " + reason());
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (rc != 0) {
    const std::string why = reason();
    discard();
    throw FileError("cannot write '" + path_ + "': " + why);
  }
  if (std::rename(temp_path_.c_str(), target_.c_str()) != 0) {
    const std::string why = reason();
    discard();
    throw FileError("cannot rename into '" + path_ + "': " + why);
  }
  forget_temp_file(temp_path_);
  committed_ = true;
}

void check_output_path(const std::string& path) {
  if (path == "-") return;
  if (path.empty()) throw FileError("an output file name is empty");
  const std::string target = link_target(path);
  const std::string shown = target == path ? "'" + path + "'" : "'" + path + "' (a link to '" + target + "')";
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw FileError("cannot write " + shown + ": it is " + kind_of(st.st_mode) +
                      "; ncpost writes only regular files, give a file name");
  } else if (errno != ENOENT) {
    throw FileError("cannot write " + shown + ": " + reason());
  }
  const std::string folder = folder_of(target);
  if (::stat(folder.c_str(), &st) != 0)
    throw FileError("cannot write " + shown + ": the folder '" + folder + "' does not exist (" + reason() + ")");
  if (!S_ISDIR(st.st_mode)) throw FileError("cannot write " + shown + ": '" + folder + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw FileError("cannot write " + shown + ": cannot create a file in '" + folder + "': " + reason());
}

void write_file_atomically(const std::string& path, std::string_view data) {
  AtomicFile f(path);
  f.write(data);
  f.commit();
}

}  // namespace ncpost
