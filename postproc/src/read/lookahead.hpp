// SPDX-License-Identifier: Apache-2.0
#pragma once
// The post's read-ahead (PostOptions::threads = 2): while the post writes one part of the program,
// a reading thread parses the next CL records and a solving thread solves their motions
// (KinematicModel::solve_quiet, the expensive part under `--model`), each from the commands of the
// motion before it, with working data of its own (SolverData; the post records the figures of the
// motions it uses in its own). Three stages on two cores: reading is light, so it shares a core with the post.
//
// The post uses a motion solved ahead only when it reaches that motion with the same CL point and
// the same previous commands, bit for bit (`AheadSolve::fits`): anything that made the post's
// sequence differ (arcs, cycles, retracts) just means it solves the motion itself. The program
// is therefore the same as with one thread. Only solvers whose commands depend on nothing the
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

/// One record in input order, with the reader's notices about it and its motion solved ahead.
struct AheadItem {
  std::optional<cl::Record> record;  ///< nullopt: the end of the input (or `error`)
  std::vector<std::string> notices;
  std::optional<AheadSolve> solved;
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

  /// Starts reading. `reader` and `solver` must outlive the object. Motions are solved ahead only
  /// for a solver that is concurrent(); otherwise the records are only read ahead.
  Lookahead(cl::Reader& reader, const KinematicModel& solver);
  ~Lookahead();  ///< stops the threads (also when the post failed half-way)
  Lookahead(const Lookahead&) = delete;
  Lookahead& operator=(const Lookahead&) = delete;

  /// The next record in input order; waits while the other threads are behind.
  AheadItem next();

 private:
  void read();
  void solve();

  cl::Reader& reader_;
  const KinematicModel& solver_;
  SolverData solving_data_;  ///< the solver's working data on the solving thread (that thread's only)
  BatchQueue parsed_{kMaxBatches};
  BatchQueue solved_{kMaxBatches};
  alignas(64) std::vector<AheadItem> current_;  ///< the batch being handed out (post's thread only)
  std::size_t position_ = 0;
  std::thread reading_;
  std::thread solving_;
};

}  // namespace ncpost::detail
