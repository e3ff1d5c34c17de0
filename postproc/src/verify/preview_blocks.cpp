// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/preview_blocks.hpp"

#include <fmt/format.h>

#include "ncpost/postproc/solve/unreachable.hpp"

#include <optional>
#include <variant>

namespace ncpost::preview {
namespace {

class Previewer {
 public:
  Previewer(const std::string& input, const KinematicModel& solver, const BlockEvaluator& evaluator,
            const std::function<void(const BlockRow&)>& sink, const std::function<void(std::size_t)>& progress)
      : input_(input),
        solver_(solver),
        evaluator_(evaluator),
        sink_(sink),
        progress_(progress),
        previous_q_(solver.words().home()) {}

  PreviewStats run(cl::Reader& reader) {
    while (auto record = reader.next()) {
      std::visit([this](const auto& r) { on(r); }, *record);
      for (auto& n : reader.take_notices()) stats_.notices.push_back(std::move(n));
    }
    return stats_;
  }

 private:
  void on(const cl::Motion& m) {
    ++stats_.motions;
    if (progress_ && stats_.motions % 4096 == 0) progress_(stats_.motions);
    AxisPosition q;
    if (m.rotary_rad) {
      q = solver_.with_rotary(m.point, *m.rotary_rad, data_);
    } else {
      const IkOutcome ik = solver_.solve(m.point, previous_q_, data_);
      if (!ik.ok())
        throw PreviewInfeasible(
            unreachable_message(input_, m.where.line, solver_, data_, m.point, previous_q_, ik.failure.message));
      q = *ik.position;
    }
    const bool cutting = !(m.rapid || m.from) && cycle_ == cl::Cycle::Kind::off;
    if (circle_pending_) {
      circle_pending_ = false;
      if (cutting) stats_.notices.push_back(fmt::format("{}:{}: CIRCLE previewed as its chord", input_, m.where.line));
    }
    if (have_position_ && cutting) {
      BlockRow row;
      row.block = ++stats_.blocks;
      row.line = m.where.line;
      row.cl = {previous_cl_, m.point, previous_q_, q};
      evaluator_.evaluate(row);
      sink_(row);
    }
    previous_cl_ = m.point;
    previous_q_ = q;
    have_position_ = true;
  }
  void on(const cl::Circle&) { circle_pending_ = true; }
  void on(const cl::Cycle& c) {
    if (c.kind != cl::Cycle::Kind::off && cycle_ == cl::Cycle::Kind::off)
      stats_.notices.push_back(fmt::format("{}:{}: drilling-cycle holes are not previewed", input_, c.where.line));
    cycle_ = c.kind;
  }
  template <class Other>
  void on(const Other&) {}

  const std::string& input_;
  const KinematicModel& solver_;
  SolverData data_;  ///< the solver's working data (this thread's)
  const BlockEvaluator& evaluator_;
  const std::function<void(const BlockRow&)>& sink_;
  const std::function<void(std::size_t)>& progress_;
  PreviewStats stats_;
  ClPoint previous_cl_;
  AxisPosition previous_q_;
  bool have_position_ = false;
  bool circle_pending_ = false;
  cl::Cycle::Kind cycle_ = cl::Cycle::Kind::off;
};

}  // namespace

PreviewStats run_preview(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         const BlockEvaluator& evaluator, const std::function<void(const BlockRow&)>& sink,
                         const std::function<void(std::size_t)>& progress) {
  Previewer p(input_name, solver, evaluator, sink, progress);
  return p.run(reader);
}

}  // namespace ncpost::preview
