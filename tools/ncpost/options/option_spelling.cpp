// SPDX-License-Identifier: Apache-2.0
#include "option_spelling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace ncpost::cli {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// " did you mean X?" for the closest of `known` within a third of the word's length, else "".
std::string suggestion(const std::string& word, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& k : known)
    if (const std::size_t d = edit_distance(word, k); d < best_d) {
      best_d = d;
      best = k;
    }
  return best.empty() ? std::string() : fmt::format("; did you mean {}?", best);
}

std::vector<std::string> long_names(const CLI::App& app) {
  std::vector<std::string> names{"--help"};
  for (const CLI::Option* o : app.get_options())
    for (const auto& l : o->get_lnames()) names.push_back("--" + l);
  return names;
}

}  // namespace

std::string misspelt_option(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* sub = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (!sub) {
      if (arg.empty() || arg[0] == '-') continue;  // --help, --version: CLI11 handles them
      for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
        if (s->get_name() == arg) sub = s;
      if (sub) continue;
      std::vector<std::string> names;
      for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
        names.push_back(s->get_name());
      return fmt::format("unknown subcommand '{}'{}", arg, suggestion(arg, names));
    }
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    const std::string name = arg.substr(0, arg.find('='));
    const std::vector<std::string> known = long_names(*sub);
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    return fmt::format("unknown option {}{}", name, suggestion(name, known));
  }
  return {};
}

}  // namespace ncpost::cli
