// SPDX-License-Identifier: Apache-2.0
#include "file_checks.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <climits>
#include <cstdlib>
#include <optional>

#include "commands.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"

namespace ncpost::cli {
namespace {

/// What a path names: device and inode of an existing file, else the absolute path it would get.
struct Identity {
  std::optional<std::pair<dev_t, ino_t>> inode;
  std::string would_be;
  bool same(const Identity& o) const {
    if (inode || o.inode) return inode && o.inode && *inode == *o.inode;
    return !would_be.empty() && would_be == o.would_be;
  }
};

Identity identity_of(const std::string& path) {
  Identity id;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.inode = std::make_pair(st.st_dev, st.st_ino);
    return id;
  }
  const auto slash = path.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  char buf[PATH_MAX];
  if (::realpath(folder.c_str(), buf)) id.would_be = std::string(buf) + "/" + path.substr(slash + 1);
  return id;
}

bool skipped(const std::string& path) { return path.empty() || path == "-"; }

}  // namespace

void check_files(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  std::vector<std::pair<const NamedPath*, Identity>> seen;
  for (const NamedPath& in : inputs)
    if (!skipped(in.path)) seen.emplace_back(&in, identity_of(in.path));
  const std::size_t input_count = seen.size();
  for (const NamedPath& out : outputs) {
    if (skipped(out.path)) continue;
    const Identity id = identity_of(out.path);
    for (std::size_t k = 0; k < seen.size(); ++k)
      if (id.same(seen[k].second)) {
        const NamedPath& other = *seen[k].first;
        throw UsageError(fmt::format("{} '{}' is the same file as {} '{}': writing it would {}; give another file name",
                                     out.option, out.path, other.option, other.path,
                                     k < input_count ? "replace an input" : "put two results into one file"));
      }
    seen.emplace_back(&out, id);
  }
  for (const NamedPath& out : outputs)
    if (!skipped(out.path)) check_output_path(out.path);
}

}  // namespace ncpost::cli
