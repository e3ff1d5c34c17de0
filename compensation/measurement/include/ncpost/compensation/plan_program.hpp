// SPDX-License-Identifier: Apache-2.0
#pragma once
// The NC program of a measurement plan (plans.hpp, laser_plan.hpp) as neutral records: moves in
// the machine's axes, dwells, program stops and comments, in the order the control runs them. No
// word of any control is named here; the NC writer of postproc (plan_nc.hpp) writes the records
// in a dialect (its block numbers, comment style and sanitising, word formats, program start and
// end), so `ncpost plan --dialect` works for every dialect a post can be written in.
#include <string>
#include <vector>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost::comp {

/// One record of a measurement program.
struct PlanRecord {
  enum class Kind {
    comment,       ///< a comment line (`note`)
    rapid,         ///< a rapid to `pose` (set-up move, no instrument on the machine)
    feed,          ///< a straight move to `pose` at `feed` mm/min
    inverse_time,  ///< a straight move to `pose` taking 1/`feed` minutes (G93 where the dialect has it)
    dwell,         ///< a dwell of `seconds` (the instrument is read)
    stop,          ///< a program stop: the operator mounts or removes the instrument, then resumes
  };
  Kind kind = Kind::comment;
  AxisPosition pose;     ///< rapid, feed, inverse_time: where the axes go (mm, rad)
  double feed = 0.0;     ///< feed: mm/min; inverse_time: 1/min
  double seconds = 0.0;  ///< dwell
  /// inverse_time: the time of the move is part of the measurement (the rows' time stamps); a
  /// dialect without inverse-time feed cannot run it. False: any safe speed will do.
  bool timed = false;
  std::string note;  ///< comment: its text; else written as a comment on the block (may be empty)
};

/// A measurement program: the program name (sanitised by the writer), header comments, records.
struct PlanProgram {
  std::string name;
  std::vector<std::string> header;
  std::vector<PlanRecord> records;

  void comment(std::string text) {
    records.push_back({PlanRecord::Kind::comment, {}, 0.0, 0.0, false, std::move(text)});
  }
  void rapid(const AxisPosition& q) { records.push_back({PlanRecord::Kind::rapid, q, 0.0, 0.0, false, {}}); }
  void feed(const AxisPosition& q, double mm_min, std::string note = {}) {
    records.push_back({PlanRecord::Kind::feed, q, mm_min, 0.0, false, std::move(note)});
  }
  void inverse_time(const AxisPosition& q, double per_min, bool timed) {
    records.push_back({PlanRecord::Kind::inverse_time, q, per_min, 0.0, timed, {}});
  }
  void dwell(double seconds, std::string note) {
    records.push_back({PlanRecord::Kind::dwell, {}, 0.0, seconds, false, std::move(note)});
  }
  void stop(std::string note) { records.push_back({PlanRecord::Kind::stop, {}, 0.0, 0.0, false, std::move(note)}); }
};

}  // namespace ncpost::comp
