// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/compare_sessions.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::comp {
namespace {

/// The session dates as days since the first; refuses a date that precedes the one before it.
void date_sessions(Comparison& c) {
  std::vector<std::optional<double>> days;
  c.dated = true;
  for (const Session& s : c.sessions) {
    days.push_back(days_since_epoch(s.date));
    c.dated = c.dated && days.back().has_value();
  }
  for (std::size_t k = 0; k < c.sessions.size(); ++k) c.day.push_back(c.dated ? *days[k] - *days[0] : double(k + 1));
  for (std::size_t k = 1; c.dated && k < c.sessions.size(); ++k)
    if (c.day[k] < c.day[k - 1])
      throw InputError({c.sessions[k].file, 0, 0},
                       fmt::format("dated {}, before '{}' ({}) given ahead of it: give the sessions in the order they "
                                   "were measured (BEFORE first)",
                                   c.sessions[k].date, c.sessions[k - 1].file, c.sessions[k - 1].date));
}

FigureTrend& trend_of(Comparison& c, const SessionFigure& f) {
  for (FigureTrend& t : c.figures)
    if (t.name == f.name) return t;
  const std::size_t n = c.sessions.size();
  FigureTrend t;
  t.name = f.name;
  t.kind = f.kind;
  t.unit = f.unit;
  t.value.resize(n);
  t.expanded.assign(n, 0.0);
  t.verdict.resize(n);
  c.figures.push_back(t);
  return c.figures.back();
}

void close_trend(FigureTrend& t) {
  for (std::size_t k = 0; k < t.value.size(); ++k)
    if (t.value[k]) {
      if (t.first < 0) t.first = int(k);
      t.last = int(k);
    }
  if (t.first < 0 || t.first == t.last) return;
  const double a = *t.value[std::size_t(t.first)], b = *t.value[std::size_t(t.last)];
  const double ua = t.expanded[std::size_t(t.first)], ub = t.expanded[std::size_t(t.last)];
  t.change = b - a;
  t.change_U = std::sqrt(ua * ua + ub * ub);
  t.outcome = ua > 0 && ub > 0 ? change_outcome(a, b, t.change_U) : "not proven (no U)";
}

}  // namespace

std::string change_outcome(double first, double last, double change_U) {
  if (!(std::abs(last - first) > change_U)) return "no change proven";
  return std::abs(last) < std::abs(first) ? "better (proven)" : "worse (proven)";
}

Comparison compare_sessions(const std::vector<Session>& sessions, const Tolerances& tolerances) {
  if (sessions.size() < 2) throw std::invalid_argument("compare_sessions: needs at least two sessions");
  Comparison c;
  c.sessions = sessions;
  for (const Session& s : sessions)
    if (s.test != sessions.front().test)
      throw InputError({s.file, 0, 0},
                       fmt::format("not the same test as '{}': {} here, {} there; compare the same test "
                                   "before and after",
                                   sessions.front().file, s.test, sessions.front().test));
  date_sessions(c);
  for (std::size_t k = 0; k < sessions.size(); ++k)
    for (const SessionFigure& f : sessions[k].figures) {
      FigureTrend& t = trend_of(c, f);
      t.value[k] = f.value;
      t.expanded[k] = f.expanded();
      t.tolerance = f.kind.empty() ? std::nullopt : tolerances.of(f.kind);
      if (t.tolerance && f.budget) t.verdict[k] = decide(f.value, f.expanded(), *t.tolerance);
    }
  for (FigureTrend& t : c.figures) close_trend(t);
  return c;
}

}  // namespace ncpost::comp
