// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/plan_nc.hpp"

#include <fmt/format.h>

#include <sstream>
#include <stdexcept>

#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/write/cycle_words.hpp"

namespace ncpost {
namespace {

/// Feed of an untimed inverse-time move (a guided turn with the instrument on) in a dialect that
/// has no inverse-time feed: slow, in the control's units of the block (mm/min, deg/min).
constexpr double kUntimedMoveFeed = 500.0;

NcMotion motion_to(const Machine& m, const AxisPosition& q) {
  NcMotion mo;
  for (std::size_t a = 0; a < m.axes.size() && a < mo.values.size(); ++a) {
    const double v = q[static_cast<int>(a)];
    mo.values[a] = m.axes[a].is_rotary() ? rad_to_deg(v) : v;
  }
  return mo;
}

/// `blocks` with `note` at the end of the last one.
void blocks_with_note(NcWriter& w, const std::vector<std::string>& blocks, const std::string& note) {
  for (std::size_t i = 0; i < blocks.size(); ++i) w.block(blocks[i], i + 1 == blocks.size() ? note : std::string());
}

void write_record(NcWriter& w, const Machine& m, const comp::PlanRecord& r) {
  using Kind = comp::PlanRecord::Kind;
  switch (r.kind) {
    case Kind::comment:
      w.comment(r.note);
      return;
    case Kind::stop:
      blocks_with_note(w, w.dialect().program_stop, r.note);
      return;
    case Kind::dwell:
      blocks_with_note(w, dwell_blocks(w.dialect(), r.seconds), r.note);
      return;
    case Kind::rapid: {
      NcMotion mo = motion_to(m, r.pose);
      mo.rapid = true;
      w.motion(mo, r.note);
      return;
    }
    case Kind::feed: {
      NcMotion mo = motion_to(m, r.pose);
      mo.feed = r.feed;
      w.motion(mo, r.note);
      return;
    }
    case Kind::inverse_time: {
      NcMotion mo = motion_to(m, r.pose);
      if (!w.dialect().motion.inverse_time.empty()) {
        mo.feed_mode = NcMotion::FeedMode::inverse_time;
        mo.feed = r.feed;
      } else if (r.timed) {
        throw std::invalid_argument(fmt::format(
            "the {} dialect ({}) has no inverse-time feed ([motion] inverse_time is empty): the measuring move "
            "through the rows must take the rows' time steps; choose a dialect with inverse-time feed (G93)",
            w.dialect().name, w.dialect().file));
      } else {
        mo.feed = kUntimedMoveFeed;
      }
      // a timed move to where the axes are (two rows at one pose) writes no block: its time is a dwell
      if (!w.motion(mo, r.note) && r.timed)
        blocks_with_note(w, dwell_blocks(w.dialect(), 60.0 / r.feed), "the next row at the same pose");
      return;
    }
  }
}

}  // namespace

void write_plan_program(NcWriter& w, const Machine& m, const comp::PlanProgram& program) {
  w.begin_program(program.name, program.header);
  for (const comp::PlanRecord& r : program.records) write_record(w, m, r);
  w.end_program();
}

std::string plan_program_text(const Machine& m, const comp::PlanProgram& program, const Dialect& dialect) {
  std::ostringstream text;
  AtomicFile sink(text);
  NcWriter writer(sink, dialect, axis_letters(m));
  write_plan_program(writer, m, program);
  sink.commit();
  return text.str();
}

}  // namespace ncpost
