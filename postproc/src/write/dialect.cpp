// SPDX-License-Identifier: Apache-2.0
// Finding a dialect: a user's file, or a built-in one from the editable copies (environment,
// installation) or, failing those, the copy embedded at build time (builtin_dialects.cpp.in).
#include "ncpost/postproc/write/dialect.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "ncpost/machines/input_error.hpp"

namespace ncpost {
namespace detail {
struct EmbeddedDialect {
  const char* name;
  const char* text;
};
extern const EmbeddedDialect kEmbeddedDialects[];
extern const std::size_t kEmbeddedDialectCount;
}  // namespace detail

namespace {

namespace fs = std::filesystem;

Dialect read_dialect_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError({path, 0, 0}, "cannot open the dialect file; expected a built-in name or a readable .toml file");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_dialect(s.str(), path);
}

/// The editable copy of built-in `name`: $NCPOST_DIALECT_DIR, else share/ncpost/dialects beside the
/// executable's bin/ (an installation); empty when neither has it.
std::string editable_copy(const std::string& name) {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("NCPOST_DIALECT_DIR"); env && *env) dirs.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share" / "ncpost" / "dialects");
  for (const fs::path& dir : dirs) {
    const fs::path file = dir / (name + ".toml");
    if (fs::is_regular_file(file, ec)) return file.string();
  }
  return {};
}

}  // namespace

const std::vector<std::string>& builtin_dialect_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (std::size_t i = 0; i < detail::kEmbeddedDialectCount; ++i) n.emplace_back(detail::kEmbeddedDialects[i].name);
    return n;
  }();
  return names;
}

Dialect dialect_named(const std::string& name_or_path) {
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       (name_or_path.size() > 5 && name_or_path.compare(name_or_path.size() - 5, 5, ".toml") == 0);
  if (is_path) return read_dialect_file(name_or_path);
  for (std::size_t i = 0; i < detail::kEmbeddedDialectCount; ++i) {
    const detail::EmbeddedDialect& e = detail::kEmbeddedDialects[i];
    if (name_or_path != e.name) continue;
    if (const std::string file = editable_copy(e.name); !file.empty()) return read_dialect_file(file);
    return parse_dialect(e.text, std::string("<built-in>/") + e.name + ".toml");
  }
  std::string list;
  for (const auto& n : builtin_dialect_names()) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown dialect '" + name_or_path + "' (expected " + list +
                              ", or the path of a dialect file)");
}

std::string with_value(const std::string& words, const std::string& placeholder, const std::string& value) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = words.find(placeholder, from)) != std::string::npos; from = at + placeholder.size())
    out.append(words, from, at - from).append(value);
  return out.append(words, from, std::string::npos);
}

std::string without_word(const std::string& words, const std::string& placeholder) {
  std::string out;
  std::size_t from = 0;
  while (from <= words.size()) {
    std::size_t end = words.find(' ', from);
    if (end == std::string::npos) end = words.size();
    const std::string word = words.substr(from, end - from);
    if (!word.empty() && word.find(placeholder) == std::string::npos) out += (out.empty() ? "" : " ") + word;
    from = end + 1;
  }
  return out;
}

std::string with_tool(const std::string& words, int tool, std::optional<int> length_register) {
  return with_value(with_value(words, "{tool}", std::to_string(tool)), "{length}",
                    std::to_string(length_register.value_or(tool)));
}

}  // namespace ncpost
