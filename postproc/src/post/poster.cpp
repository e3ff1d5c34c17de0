// SPDX-License-Identifier: Apache-2.0
// The post's driver: the record loop and the records that move nothing (poster.hpp).
#include "post/poster.hpp"

#include <fmt/format.h>

#include "ncpost/postproc/write/cycle_words.hpp"
#include "write/tool_offset_blocks.hpp"

namespace ncpost {
namespace detail {

Poster::Poster(const std::string& input, const KinematicModel& solver, SolverData& data, NcWriter& writer,
               const PostOptions& options)
    : input_(input),
      solver_(solver),
      hooks_(post_hooks_of(solver)),
      data_(data),
      writer_(writer),
      options_(options),
      machine_(solver.machine()),
      words_(solver.words()) {
  previous_.q = words_.home();  // the program starts from home, sized for the model's axes
  last_executed_ = words_.home();
  if (options_.verify) {  // --verify reads every motion block back as written (read_back.hpp)
    read_back_.emplace(writer_.dialect(), writer_.letters());
    writer_.keep_last_line(true);
  }
}

PostSummary Poster::run(cl::Reader& reader) {
  writer_.begin_program(options_.program_name, options_.header_comments);
  std::optional<Lookahead> ahead;
  // (the post cuts motions with its subdivider except under RTCP: write_motion)
  const Subdivider* cutter = options_.subdivide && !options_.rtcp ? &options_.subdivide : nullptr;
  if (options_.threads > 1) ahead.emplace(reader, solver_, cutter, options_.subdivide_rapids);
  // the next record from the input: read ahead (2 threads) or read here, errors kept in place
  const Fetch fetch = [&]() -> AheadItem { return ahead ? ahead->next() : read_item(reader); };
  for (;;) {
    AheadItem item;
    if (!pending_.empty()) {
      item = std::move(pending_.front());
      pending_.pop_front();
    } else {
      item = carry_ ? std::move(*carry_) : fetch();
      carry_.reset();
      if (!continues_unplanned_run(item) && starts_run(item)) {
        plan_run(std::move(item), fetch);
        continue;
      }
    }
    if (item.error) std::rethrow_exception(item.error);
    if (!item.record) break;
    ahead_ = item.solved ? &*item.solved : nullptr;
    ahead_cut_ = item.cut ? &*item.cut : nullptr;
    planned_rotary_ = item.planned_rotary_rad;
    std::visit([this](const auto& r) { on(r); }, *item.record);
    ahead_ = nullptr;
    ahead_cut_ = nullptr;
    planned_rotary_.reset();
    for (auto& n : item.notices) summary_.notices.push_back(std::move(n));
  }
  close_plane();
  if (options_.rtcp && rtcp_on_) writer_.rtcp(false, tool_, length_register());
  writer_.end_program();
  summary_.blocks_out = writer_.blocks_written();
  return summary_;
}

void Poster::notice(cl::Location where, const std::string& what) {
  summary_.notices.push_back(fmt::format("{}:{}: {}", input_, where.line, what));
}

void Poster::on(const cl::Motion& m) {
  ++summary_.motions_in;
  if (options_.progress && summary_.motions_in % 4096 == 0) options_.progress(summary_.motions_in);
  const bool rapid = m.rapid || m.from;
  records_.resume();  // the spindle and coolant a program stop turned off
  update_plane(m, rapid);
  check_comp(m);
  if (pending_circle_) {
    const cl::Circle c = *pending_circle_;
    pending_circle_.reset();
    if (have_position_) {
      move_along_arc(c, m, rapid);
      return;
    }
  }
  if (cycle_.kind != cl::Cycle::Kind::off && !rapid) {
    drill(m);
    return;
  }
  move_to(m.point, m.where.line, rapid, words_.angles_are_programmed ? m.rotary_rad : std::nullopt);
}

void Poster::on(const cl::Feed& f) {
  if (auto n = records_.feed(f)) notice(f.where, *n);
}
void Poster::on(const cl::Spindle& s) { records_.spindle(s); }
void Poster::on(const cl::Coolant& c) { records_.coolant(c); }
void Poster::on(const cl::Circle& c) { pending_circle_ = c; }
void Poster::on(const cl::Cycle& c) {
  cycle_ = c;
  if (c.kind == cl::Cycle::Kind::off) writer_.end_cycle();
}
void Poster::on(const cl::Comment& c) { records_.comment(c); }
void Poster::on(const cl::Unsupported& u) { records_.unsupported(u); }
void Poster::on(const cl::Dwell& d) {
  records_.resume();  // a dwell after a stop waits with the spindle turning (it may be its run-up)
  for (const std::string& b : dwell_blocks(writer_.dialect(), d.seconds)) writer_.block(b);
}
/// A program stop moves nothing: it is written where it stands, also in a tilted work plane (the
/// plane, like every modal frame, holds across M0/M1 on the controls of the dialects).
void Poster::on(const cl::Stop& s) { records_.stop(s); }
void Poster::on(const cl::End&) {}
void Poster::on(const cl::ToolOffset& t) { detail::write_tool_offset(writer_, t, input_); }

}  // namespace detail

PostSummary post_program(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         NcWriter& writer, const PostOptions& options, SolverData& data) {
  detail::Poster poster(input_name, solver, data, writer, options);
  return poster.run(reader);
}

PostSummary post_program(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         NcWriter& writer, const PostOptions& options) {
  SolverData data;
  return post_program(reader, input_name, solver, writer, options, data);
}

}  // namespace ncpost
