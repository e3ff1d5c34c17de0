// SPDX-License-Identifier: Apache-2.0
#include "verify/post_account_fill.hpp"

#include <fmt/format.h>

namespace ncpost::detail {

PostAccount account_of(const PostRequest& r, const std::optional<double>& tolerance_mm) {
  const bool has_model = r.machine->has_model(), has_verify_on = r.machine->has_verify_on();
  PostAccount acc;
  acc.input_name = r.input_name;
  acc.machine_name = fmt::format("{} ({})", r.machine->name(), r.machine_source);
  acc.model_name = has_model ? r.model_source : std::string();
  acc.executed_on = has_verify_on ? "the machine of " + r.verify_on_source
                    : has_model   ? "the machine of " + r.model_source + " (as compensated)"
                                  : "the nominal machine";
  acc.dialect_name = r.dialect.name;
  acc.inputs.push_back({"CL input", r.input_file.empty() ? r.input_name : r.input_file, r.input_name});
  if (!r.machine_source.empty()) acc.inputs.push_back({"machine file", r.machine_source});
  if (has_model) acc.inputs.push_back({"error model", r.model_source});
  if (has_verify_on) acc.inputs.push_back({"executed on (model)", r.verify_on_source});
  acc.method_name = r.nonlinear == nonlinear::Method::harmonic ? "harmonic" : "adaptive";
  acc.tolerance_mm = tolerance_mm.value_or(0.0);
  return acc;
}

void add_posted(PostAccount& acc, const PostSummary& s) {
  acc.motions_in = s.motions_in;
  acc.blocks_out = s.blocks_out;
  acc.after = s.verify;
  acc.notices = s.notices;
}

void add_before(PostAccount& acc, int line, double error_mm) {
  ++acc.before_blocks;
  if (error_mm > acc.before_max_mm) {
    acc.before_max_mm = error_mm;
    acc.before_worst_line = line;
  }
  acc.before_series.add(line, error_mm);
}

void close_before(PostAccount& acc, double sum_mm) {
  acc.before_mean_mm = acc.before_blocks ? sum_mm / static_cast<double>(acc.before_blocks) : 0.0;
}

void measure_before(cl::Reader& reader, const KinematicModel& nominal, const preview::BlockEvaluator& executed,
                    const PostRequest& r, PostAccount& account) {
  double sum = 0.0;
  try {
    preview::run_preview(
        reader, r.input_name, nominal, executed,
        [&](const preview::BlockRow& row) {
          const double e = row.exact.max_error_mm;
          sum += e;
          add_before(account, row.line, e);
          account.path.add_before(row.line, row.cl.end.tip_mm, e);
        },
        r.progress.measuring);
  } catch (const preview::PreviewInfeasible& e) {
    throw Infeasible(e.what());
  }
  close_before(account, sum);
}

}  // namespace ncpost::detail
