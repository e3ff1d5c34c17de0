// SPDX-License-Identifier: Apache-2.0
#pragma once
// The page every HTML report starts with: one style sheet, a title, and the provenance table a
// metrologist needs to trust the figures — each input file with its SHA-256, the machine, the
// model, the date (UTC) and the ncpost version. Self-contained: no scripts from elsewhere, no
// network. Units in the reports: µm and µrad unless a heading says otherwise.
#include <string>
#include <vector>

namespace ncpost::report {

/// Text escaped for HTML content and attribute values (& < > " ').
std::string escape(const std::string& text);

/// The last component of a path ("data/ballbar.csv" -> "ballbar.csv").
std::string base_name(const std::string& path);

struct InputFile {
  std::string role;        ///< "machine", "measurement", "CL input", "model", ...
  std::string path;        ///< as given; its bytes are hashed when the page is made
  std::string shown = {};  ///< the name shown, if not the path (e.g. "<stdin>" for its spool file)
};

struct Provenance {
  std::string title;              ///< <title> and <h1>
  std::string machine;            ///< the machine's name (and file)
  std::string model;              ///< the error model (file, or what was identified); empty: none
  std::vector<InputFile> inputs;  ///< named with their SHA-256
  std::vector<std::pair<std::string, std::string>> extra;  ///< further rows (label, HTML)
};

/// "2026-11-26T00:41:07Z": now, or SOURCE_DATE_EPOCH when set (reproducible builds of reports).
std::string utc_now();

/// <!DOCTYPE html> … <body><h1>title</h1> and the provenance table.
std::string page_start(const Provenance& provenance);
/// The provenance table alone (inputs with SHA-256, machine, model, date, version).
std::string provenance_table(const Provenance& provenance);
/// </body></html>
std::string page_end();

}  // namespace ncpost::report
