// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/summary_page.hpp"

#include <fmt/format.h>

#include <utility>
#include <vector>

#include "ncpost/report/html_page.hpp"
#include "ncpost/report/sha256.hpp"
#include "ncpost/version.hpp"

namespace ncpost::comp {
namespace {

using report::escape;

constexpr const char* kStyle =
    "<style>@page{size:A4;margin:10mm 12mm}body{font-family:sans-serif;font-size:9pt;line-height:1.15;color:#111;"
    "margin:0 auto;max-width:186mm}h1{font-size:13pt;margin:0 0 3px}h2{font-size:10pt;margin:7px 0 2px}"
    "table{border-collapse:collapse;width:100%;margin:1px 0}td,th{border:1px solid #bbb;padding:1px 4px;"
    "text-align:left;vertical-align:top}th{background:#eee}.hash{font-family:monospace;font-size:6.5pt;color:#444}"
    ".pass{color:#0a7a2a;font-weight:bold}.fail{color:#c0241b;font-weight:bold}.unproven{color:#a05a00;"
    "font-weight:bold}.note{font-size:8pt;color:#333;margin:2px 0}ul.note{padding-left:16px}.sign td{height:9mm}"
    ".facts th{white-space:nowrap;width:1%}.sign{break-inside:avoid;page-break-inside:avoid}@media "
    "print{a{color:inherit;text-decoration:none}}</style>";

const char* verdict_class(const std::string& v) {
  return v == "PASS" ? "pass" : v == "FAIL" ? "fail" : v.empty() ? "" : "unproven";
}

/// "name 1a2b3c4d5e6f" (the first 12 hex digits of its SHA-256; the full report gives all 64).
std::string named_with_hash(const std::string& path) {
  const auto hash = report::file_sha256_hex(path);
  return escape(report::base_name(path)) + " <span class=\"hash\">" + (hash ? hash->substr(0, 12) : "(not hashed)") +
         "</span>";
}

/// The facts, then the inputs by role, each role in one row (27 laser lines stay one row).
std::string facts_table(const IdentificationSummary& s) {
  std::string h = "<table class=\"facts\">";
  for (const auto& [k, v] : s.facts) h += "<tr><th>" + escape(k) + "</th><td>" + escape(v) + "</td></tr>";
  std::vector<std::pair<std::string, std::vector<std::string>>> roles;
  for (const auto& [role, path] : s.inputs) {
    if (roles.empty() || roles.back().first != role) roles.push_back({role, {}});
    roles.back().second.push_back(named_with_hash(path));
  }
  for (const auto& [role, files] : roles)
    h += fmt::format("<tr><th>{}{}</th><td>{}</td></tr>", escape(role),
                     files.size() > 1 ? fmt::format(" ({} files)", files.size()) : "",
                     fmt::format("{}", fmt::join(files, "; ")));
  h += "<tr><th>SHA-256</th><td class=\"note\">the first 12 hex digits of each input; all 64 in the full "
       "report</td></tr>";
  return h + fmt::format("<tr><th>report date (UTC)</th><td>{}</td></tr><tr><th>ncpost</th><td>{}</td></tr></table>",
                         report::utc_now(), escape(ncpost::version()));
}

std::string figures_table(const IdentificationSummary& s) {
  std::string h = "<table><tr><th>figure</th><th>value ± U (k = 2)</th><th>tolerance</th><th>verdict</th></tr>";
  for (const SummaryFigure& f : s.figures)
    h += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"{}\">{}</td></tr>", escape(f.what),
                     escape(f.value), escape(f.against.empty() ? "—" : f.against), verdict_class(f.verdict),
                     escape(f.verdict.empty() ? "—" : f.verdict));
  return h + "</table>";
}

std::string signature_block() {
  return "<h2>Signatures</h2><table class=\"sign\"><tr><th style=\"width:22%\"></th><th>name</th><th "
         "style=\"width:18%\">"
         "date</th><th style=\"width:32%\">signature</th></tr><tr><th>measured by</th><td></td><td></td><td></td></tr>"
         "<tr><th>evaluated by</th><td></td><td></td><td></td></tr><tr><th>approved by</th><td></td><td></td><td></td>"
         "</tr></table>";
}

}  // namespace

std::string summary_page_html(const IdentificationSummary& s) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escape(s.title) +
                  " (summary)</title>" + kStyle + "</head><body>\n<h1>" + escape(s.title) + "</h1>";
  if (!s.full_report.empty())
    h += "<p class=\"note\">Summary of one page; the full report with every plot and budget: <a href=\"" +
         escape(report::base_name(s.full_report)) + "\">" + escape(report::base_name(s.full_report)) + "</a>.</p>";
  h += facts_table(s) + "<h2>Measurement conditions</h2><table>";
  for (const std::string& c : s.conditions) h += "<tr><td>" + escape(c) + "</td></tr>";
  if (s.conditions.empty()) h += "<tr><td>no data files named</td></tr>";
  h += "</table><h2>Key figures and verdicts</h2>" + figures_table(s) +
       "<p class=\"note\">ISO 14253-1: PASS only when value + U is within the tolerance, FAIL when value − U is beyond "
       "it, NOT PROVEN between. µm for lengths, µrad for angles.</p>";
  if (!s.warnings.empty()) {
    h += "<h2>Limits</h2><ul class=\"note\">";
    for (const std::string& w : s.warnings) h += "<li>" + escape(w) + "</li>";
    h += "</ul>";
  }
  return h + signature_block() + "</body></html>\n";
}

std::string summary_path(const std::string& report_path) {
  const std::size_t slash = report_path.find_last_of('/');
  const std::size_t dot = report_path.find_last_of('.');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return has_extension ? report_path.substr(0, dot) + "-summary" + report_path.substr(dot)
                       : report_path + "-summary.html";
}

}  // namespace ncpost::comp
