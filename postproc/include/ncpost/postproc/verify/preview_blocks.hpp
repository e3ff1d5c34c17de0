// SPDX-License-Identifier: Apache-2.0
#pragma once
// `ncpost preview` (docs/cli.md; issue 4): the nonlinear error of every block of a CL program as
// the post would write it without `--tolerance` (one G1 block per CL motion), streamed block by
// block so that memory stays flat in the input size.
//
// For each feed block: the exact largest deviation of the executed tool tip from the straight CL
// segment (mm, W), where along the block (t, linear in axis space), the largest orientation error
// (rad), and the harmonic model's estimate Emax (seed 001; midpoint fit, harmonic_model.hpp) with
// how far that model is from the exact curve. Rapid and FROM motions position the tool but are not
// previewed (the control does not cut on them); a CIRCLE is previewed as its chord (with a notice);
// drilling-cycle holes are skipped.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ncpost/compensation/harmonic_model.hpp"
#include "ncpost/compensation/nonlinear_error.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"

namespace ncpost::preview {

/// One previewed block.
struct BlockRow {
  std::size_t block = 0;              ///< 1-based, previewed (feed) blocks in program order
  int line = 0;                       ///< CL line of the motion that ends the block
  nonlinear::ClBlock cl;              ///< CL end points (W) and axis positions
  nonlinear::NonlinearError exact;    ///< exact largest errors
  double harmonic_mm = 0.0;           ///< harmonic model's Emax (midpoint fit)
  double harmonic_residual_mm = 0.0;  ///< max over t of | |e(t)| − Emax·sin(πt) |
};

/// Evaluates blocks on one machine (nominal, or actual through an error functor).
class BlockEvaluator {
 public:
  virtual ~BlockEvaluator() = default;
  /// Fills `row.exact`, `row.harmonic_mm`, `row.harmonic_residual_mm` from `row.cl`.
  virtual void evaluate(BlockRow& row) const = 0;
  /// |e(t)| at t = k / samples, k = 0..samples (mm).
  virtual std::vector<double> error_curve(const nonlinear::ClBlock& block, int samples) const = 0;
};

template <class Errors>
class ModelEvaluator final : public BlockEvaluator {
 public:
  ModelEvaluator(const Machine& machine, const Setup& setup, Errors errors = {},
                 nonlinear::NonlinearErrorOptions options = {})
      : machine_(machine), setup_(setup), errors_(std::move(errors)), options_(options) {}

  void evaluate(BlockRow& row) const override {
    const nonlinear::ExecutedBlock<Errors> executed(machine_, setup_, row.cl, errors_);
    row.exact = nonlinear::nonlinear_error(executed, options_);
    const nonlinear::HarmonicModel model = nonlinear::fit_harmonic_midpoint(executed);
    row.harmonic_mm = model.amplitude_mm;
    nonlinear::MaximiseOptions m;
    m.scan_intervals = std::max(16, nonlinear::scan_intervals_for(row.cl, options_));
    row.harmonic_residual_mm =
        nonlinear::maximise_bracketed(
            [&](double t) { return std::abs(executed.at(t).error_mm() - model.magnitude_at(t)); }, 0.0, 1.0, m)
            .value;
  }

  std::vector<double> error_curve(const nonlinear::ClBlock& block, int samples) const override {
    const nonlinear::ExecutedBlock<Errors> executed(machine_, setup_, block, errors_);
    std::vector<double> out;
    for (int k = 0; k <= samples; ++k) out.push_back(executed.at(static_cast<double>(k) / samples).error_mm());
    return out;
  }

 private:
  const Machine& machine_;
  Setup setup_;
  Errors errors_;
  nonlinear::NonlinearErrorOptions options_;
};

struct PreviewStats {
  std::size_t motions = 0;
  std::size_t blocks = 0;
  std::vector<std::string> notices;
};

/// Reads the whole program, solves every motion with `solver` (continuity from the previous
/// motion; programmed rotary angles of G-code input are kept), evaluates every feed block with
/// `evaluator` and hands it to `sink`. Throws InputError (bad input) or std::runtime_error naming
/// the CL line when a motion has no admissible solution.
PreviewStats run_preview(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         const BlockEvaluator& evaluator, const std::function<void(const BlockRow&)>& sink,
                         const std::function<void(std::size_t)>& progress = {});

/// Thrown by run_preview when a CL point has no admissible solution (exit 3 in the CLI).
struct PreviewInfeasible : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ncpost::preview
