// SPDX-License-Identifier: Apache-2.0
#pragma once
// An output file written atomically (docs/cli.md): the data go to a temporary file in the same
// folder, which `commit()` flushes and renames into place. Destroyed without commit (an error on
// the way) or stopped by SIGINT/SIGTERM/SIGHUP, the temporary file is removed and an existing file
// at the path is left untouched. Only regular files are written: a device, FIFO, socket or folder
// at the path is refused (FileError, temp_files.hpp); a symbolic link is followed and its target
// replaced (the link stays); a replaced file keeps its mode.
#include <cstdio>
#include <iosfwd>
#include <string>
#include <string_view>

#include "ncpost/postproc/write/temp_files.hpp"

namespace ncpost {

class AtomicFile {
 public:
  /// Opens a temporary file beside `path` (beside its target if it is a link); "-" writes to
  /// stdout (commit only flushes). FileError, naming the path and the reason, when it cannot.
  explicit AtomicFile(std::string path);
  /// Writes into `sink` instead (the library entry point, post_request.hpp): nothing is renamed,
  /// `commit` flushes the stream; FileError when the stream fails. `sink` must outlive this.
  explicit AtomicFile(std::ostream& sink);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view data);
  std::FILE* stream() { return file_; }
  /// Flushes, syncs and renames into place. Throws FileError on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string fmt_refusal(unsigned mode) const;
  void discard();

  std::string path_;
  std::string target_;  ///< the file replaced: `path_`, or the target of the link at `path_`
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
  bool to_stdout_ = false;
  std::ostream* sink_ = nullptr;
};

/// Checks, before anything is computed, that an AtomicFile could be made at `path`: FileError (with
/// the reason) for a device, FIFO, socket or folder at the path, a missing folder or one without
/// write permission. "-" (standard output) passes.
void check_output_path(const std::string& path);

/// Writes a whole small file atomically.
void write_file_atomically(const std::string& path, std::string_view data);

}  // namespace ncpost
