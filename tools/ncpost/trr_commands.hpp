#pragma once
// `ncpost post` and `ncpost preview` on the TRR-XY machine (spec trr-xy.md): the serial
// subcommands call these first; they run the TRR-XY path when --machine is a kind = "trr-xy" file.
#include <optional>
#include <string>

#include "input_options.hpp"

namespace ncpost::cli {

struct TrrPostRequest {
  const JobOptions& job;
  const std::string& model;
  const std::optional<double>& tolerance_mm;
  const std::string& nonlinear;  ///< "adaptive" or "harmonic"
  bool rtcp;
  const std::string& dialect;
  bool verify;
  const std::string& report;
  const std::string& verify_on;
  const std::string& output;
  const std::string& input;
};

/// The exit code if the machine is a TRR-XY machine (then the post has run), else nullopt.
std::optional<int> post_if_trr_xy(const TrrPostRequest& r);

struct TrrPreviewRequest {
  const JobOptions& job;
  const std::string& model;
  const std::string& csv;
  const std::string& html;
  const std::string& input;
};

/// The exit code if the machine is a TRR-XY machine (then the preview has run), else nullopt.
std::optional<int> preview_if_trr_xy(const TrrPreviewRequest& r);

}  // namespace ncpost::cli
