// SPDX-License-Identifier: Apache-2.0
#pragma once
// The post's read-ahead (PostOptions::threads = 2): while the post writes one part of the program,
// a reading thread parses the next CL records and a solving thread solves their motions
// (KinematicModel::solve_quiet, the expensive part under `--model`), each from the commands of the
// motion before it, with working data of its own (SolverData; the post records the figures of the
// motions it uses in its own). Three or four stages on two cores, the operating system sharing them.
//
// The post uses a motion solved ahead only when it reaches that motion with the same CL point and
// the same previous commands, bit for bit (`AheadSolve::fits`): anything that made the post's
// sequence differ (arcs, cycles, retracts) just means it solves the motion itself. The program
// is therefore the same as with one thread. A fourth stage (with the post's subdivider) cuts each
// motion solved ahead from the one solved before it, used on the same condition: the post reaches
// it with those two points. Only solvers whose commands depend on nothing the
// post's progress changes (`KinematicModel::concurrent`, i.e. no reversal state) solve ahead; for
// the others the records are only read ahead.
//
// Input errors thrown by the reader surface at the record where they occurred, after everything
// before it has been posted. Memory is bounded: each stage holds at most `kMaxBatches` batches of
// `kBatchSize` records.
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"

namespace ncpost::detail {

/// A motion solved ahead.
struct AheadSolve {
  ClPoint cl;
  AxisPosition previous;  ///< the commands it was solved from
  IkOutcome ik;
  SolveFigures figures;
  bool fits(const ClPoint& point, const AxisPosition& from) const {
    return point.tip_mm == cl.tip_mm && point.axis == cl.axis && from == previous;
  }
};

/// The blocks of a motion cut ahead (PostOptions::subdivide) from the motion solved before it,
/// used only when the post cuts the same two points, bit for bit.
struct AheadCut {
  SolvedPoint from, to;
  std::vector<SolvedPoint> points;
  bool fits(const SolvedPoint& f, const SolvedPoint& t) const { return same(f, from) && same(t, to); }

 private:
  static bool same(const SolvedPoint& a, const SolvedPoint& b) {
    if (!(a.cl.tip_mm == b.cl.tip_mm && a.cl.axis == b.cl.axis && a.q == b.q)) return false;
    if (a.executed.has_value() != b.executed.has_value()) return false;
    return !a.executed || (a.executed->tip_mm == b.executed->tip_mm && a.executed->axis == b.executed->axis);
  }
};

/// One record in input order, with the reader's notices about it and its motion solved ahead.
struct AheadItem {
  std::optional<cl::Record> record;  ///< nullopt: the end of the input (or `error`)
  std::vector<std::string> notices;
  std::optional<AheadSolve> solved;
  std::optional<AheadCut> cut;  ///< its blocks from the motion solved before it
  /// The rotary angles (rad) the branch plan chose for this motion (post.cpp, branch_plan.hpp);
  /// nullopt: the solution nearest the previous commands.
  std::optional<RotaryAngles> planned_rotary_rad;
  std::exception_ptr error;  ///< the reader failed here
};

/// The next record of `reader` with the reader's notices about it; an error the reader throws is
/// kept in the item (`error`, no record) to surface where it occurred. Used by the read-ahead
/// thread and by the post reading on its own thread.
AheadItem read_item(cl::Reader& reader);

/// A bounded queue of batches between two threads; stop() wakes and releases both sides.
class BatchQueue {
 public:
  explicit BatchQueue(std::size_t capacity) : capacity_(capacity) {}
  bool push(std::vector<AheadItem>&& batch);    ///< false once stopped
  std::optional<std::vector<AheadItem>> pop();  ///< nullopt once stopped
  /// Without waiting: the oldest batch, or nullopt when there is none (or once stopped).
  std::optional<std::vector<AheadItem>> try_pop();
  /// Without waiting: queues `batch` unless the queue is full or stopped (then it is dropped).
  void offer(std::vector<AheadItem>&& batch);
  void stop();

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<AheadItem>> batches_;
  std::size_t capacity_;
  bool stopped_ = false;
};

class Lookahead {
 public:
  static constexpr std::size_t kBatchSize = 256;
  static constexpr std::size_t kMaxBatches = 8;

  /// Starts reading. `reader`, `solver` and `cutter` must outlive the object. Motions are solved
  /// ahead only for a solver that is concurrent(); otherwise the records are only read ahead. With
  /// a `cutter` (the post's subdivider where it cuts motions; nullptr: none) a fourth stage cuts
  /// each motion solved ahead from the one before it, on a thread of its own; rapids (and FROM) only
  /// with `cut_rapids`, as the post cuts them.
  Lookahead(cl::Reader& reader, const KinematicModel& solver, const Subdivider* cutter = nullptr,
            bool cut_rapids = false);
  ~Lookahead();  ///< stops the threads (also when the post failed half-way)
  Lookahead(const Lookahead&) = delete;
  Lookahead& operator=(const Lookahead&) = delete;

  /// The next record in input order; waits while the other threads are behind.
  AheadItem next();

 private:
  void read();
  void solve();
  void cut();

  cl::Reader& reader_;
  const KinematicModel& solver_;
  const Subdivider* cutter_;  ///< nullptr: no cutting stage
  bool cut_rapids_;
  /// the solver's working data on the solving thread (that thread's only), and on the cutting
  /// thread: each on cache lines of its own (both are written at every solve)
  alignas(64) SolverData solving_data_;
  alignas(64) SolverData cutting_data_;
  alignas(64) BatchQueue parsed_{kMaxBatches};  // (each queue's lock and state on lines of their own too)
  alignas(64) BatchQueue solved_{kMaxBatches};
  alignas(64) BatchQueue cut_{kMaxBatches};
  /// emptied batches the post hands back to the reading thread, which fills them again: their
  /// memory stays touched (a new batch of 256 items is about 230 kB, fresh pages each time)
  alignas(64) BatchQueue spare_{kMaxBatches};
  alignas(64) std::vector<AheadItem> current_;  ///< the batch being handed out (post's thread only)
  std::size_t position_ = 0;
  std::thread reading_;
  std::thread solving_;
  std::thread cutting_;
};

}  // namespace ncpost::detail
