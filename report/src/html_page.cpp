// SPDX-License-Identifier: Apache-2.0
#include "ncpost/report/html_page.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <ctime>

#include "ncpost/report/sha256.hpp"
#include "ncpost/version.hpp"

namespace ncpost::report {

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string utc_now() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long v = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && v >= 0) t = static_cast<std::time_t>(v);
  }
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string provenance_table(const Provenance& p) {
  std::string t = "<table class=\"provenance\">\n";
  auto row = [&](const std::string& k, const std::string& v) {
    t += fmt::format("<tr><th>{}</th><td class=n>{}</td></tr>\n", k, v);
  };
  for (const InputFile& f : p.inputs) {
    const auto hash = file_sha256_hex(f.path);
    row(escape(f.role),
        fmt::format("{} <span class=\"hash\">SHA-256 {}</span>", escape(f.shown.empty() ? f.path : f.shown),
                    hash ? *hash : std::string("(not a file: not hashed)")));
  }
  row("machine", escape(p.machine));
  row("model", p.model.empty() ? std::string("none (nominal machine)") : escape(p.model));
  for (const auto& [k, v] : p.extra) row(escape(k), v);
  row("date (UTC)", utc_now());
  row("ncpost", escape(ncpost::version()));
  return t + "</table>\n";
}

std::string page_start(const Provenance& p) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">";
  h += "<title>" + escape(p.title) + "</title>\n";
  h += "<style>body{font-family:sans-serif;margin:24px;color:#222;max-width:1200px}h1{font-size:22px}"
       "h2{font-size:17px;margin-top:28px}table{border-collapse:collapse;font-size:13px;margin:6px 0}"
       "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f0f0f0;text-align:left}"
       "td.n,th.n{text-align:left}.hash{font-family:monospace;font-size:11px;color:#555;margin-left:1em}"
       ".note{color:#555;font-size:13px}.plots{display:flex;flex-wrap:wrap;gap:12px}"
       ".plot{border:1px solid #e4e4e4;padding:6px}.pass{color:#0a7a2a;font-weight:bold}"
       ".fail{color:#c0241b;font-weight:bold}.unproven{color:#a05a00;font-weight:bold}pre{background:#f6f6f6;padding:."
       "5em}"
       "canvas{border:1px solid #ccc;cursor:grab}</style>\n</head><body>\n";
  h += "<h1>" + escape(p.title) + "</h1>\n" + provenance_table(p);
  return h;
}

std::string page_end() { return "</body></html>\n"; }

}  // namespace ncpost::report
