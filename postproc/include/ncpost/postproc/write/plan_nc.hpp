// SPDX-License-Identifier: Apache-2.0
#pragma once
// The NC program of a measurement plan (compensation/plan_program.hpp: `ncpost plan`) written by
// the NC writer (nc_writer.hpp) in a dialect: the dialect's program start and end, block numbers,
// comment style and sanitising (every note and comment passes nc_comment_text), word formats,
// dwell blocks (`[dwell]`) and program stop (`[program] stop`). A move of the plan that takes a
// given time (inverse time, G93) is written in inverse time; in a dialect without inverse-time feed
// an untimed one (a guided turn) is written per minute at a slow feed, a timed one (the continuous
// ballbar rows) cannot be run and is refused. A timed move that does not move the axes (two rows
// at one pose) is written as a dwell of its time, so the rows after it keep their time stamps.
#include <string>

#include "ncpost/compensation/plan_program.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"

namespace ncpost {

/// Writes `program` for `machine` through `writer` (begin_program ... end_program, no commit).
/// Throws std::invalid_argument when the dialect cannot run it (a timed inverse-time move and no
/// inverse-time word in the dialect).
void write_plan_program(NcWriter& writer, const Machine& machine, const comp::PlanProgram& program);

/// The text of `program` for `machine` in `dialect` (write_plan_program into a string).
std::string plan_program_text(const Machine& machine, const comp::PlanProgram& program, const Dialect& dialect);

}  // namespace ncpost
