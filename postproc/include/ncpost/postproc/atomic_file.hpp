#pragma once
// An output file written atomically (spec/cli.md): the data go to a temporary file in the same
// folder, which `commit()` flushes and renames into place. Destroyed without commit (an error on
// the way), the temporary file is removed and an existing file at the path is left untouched.
#include <cstdio>
#include <string>
#include <string_view>

namespace ncpost {

class AtomicFile {
 public:
  /// Opens a temporary file beside `path`; "-" writes to stdout (commit only flushes).
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view data);
  std::FILE* stream() { return file_; }
  /// Flushes, syncs and renames into place. Throws std::runtime_error on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
  bool to_stdout_ = false;
};

/// Writes a whole small file atomically.
void write_file_atomically(const std::string& path, std::string_view data);

}  // namespace ncpost
