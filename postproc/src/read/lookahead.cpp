// SPDX-License-Identifier: Apache-2.0
#include "read/lookahead.hpp"

#include <variant>

namespace ncpost::detail {

bool BatchQueue::push(std::vector<AheadItem>&& batch) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return stopped_ || batches_.size() < capacity_; });
  if (stopped_) return false;
  batches_.push_back(std::move(batch));
  lock.unlock();
  changed_.notify_all();
  return true;
}

std::optional<std::vector<AheadItem>> BatchQueue::pop() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return stopped_ || !batches_.empty(); });
  if (stopped_) return std::nullopt;
  std::vector<AheadItem> batch = std::move(batches_.front());
  batches_.pop_front();
  lock.unlock();
  changed_.notify_all();
  return batch;
}

std::optional<std::vector<AheadItem>> BatchQueue::try_pop() {
  std::unique_lock lock(mutex_);
  if (stopped_ || batches_.empty()) return std::nullopt;
  std::vector<AheadItem> batch = std::move(batches_.front());
  batches_.pop_front();
  lock.unlock();
  changed_.notify_all();
  return batch;
}

void BatchQueue::offer(std::vector<AheadItem>&& batch) {
  std::unique_lock lock(mutex_);
  if (stopped_ || batches_.size() >= capacity_) return;
  batches_.push_back(std::move(batch));
}

void BatchQueue::stop() {
  {
    std::lock_guard lock(mutex_);
    stopped_ = true;
  }
  changed_.notify_all();
}

Lookahead::Lookahead(cl::Reader& reader, const KinematicModel& solver, const Subdivider* cutter, bool cut_rapids)
    : reader_(reader),
      solver_(solver),
      cutter_(cutter && *cutter && solver.concurrent() ? cutter : nullptr),
      cut_rapids_(cut_rapids),
      reading_([this] { read(); }),
      solving_([this] { solve(); }) {
  if (cutter_) cutting_ = std::thread([this] { cut(); });
}

Lookahead::~Lookahead() {
  parsed_.stop();
  spare_.stop();
  solved_.stop();
  cut_.stop();
  reading_.join();
  solving_.join();
  if (cutting_.joinable()) cutting_.join();
}

AheadItem read_item(cl::Reader& reader) {
  AheadItem item;
  try {
    item.record = reader.next();
    item.notices = reader.take_notices();
  } catch (...) {
    item.record.reset();
    item.error = std::current_exception();
  }
  return item;
}

void Lookahead::read() {
  std::vector<AheadItem> batch;
  batch.reserve(kBatchSize);
  for (;;) {
    AheadItem item = read_item(reader_);
    const bool last = !item.record;
    batch.push_back(std::move(item));
    if (last || batch.size() == kBatchSize) {
      if (!parsed_.push(std::move(batch)) || last) return;  // push() fails once stopped
      batch = spare_.try_pop().value_or(std::vector<AheadItem>{});
      batch.reserve(kBatchSize);
    }
  }
}

namespace {

/// Each batch of `from`, every record of it up to the end of the input given to `each`, then on
/// into `to`; returns at the end of the input or once a queue is stopped.
template <class Each>
void relay(BatchQueue& from, BatchQueue& to, Each each) {
  for (;;) {
    std::optional<std::vector<AheadItem>> batch = from.pop();
    if (!batch) return;
    bool last = false;
    for (AheadItem& item : *batch) {
      if (!item.record) {
        last = true;
        break;
      }
      each(item);
    }
    if (!to.push(std::move(*batch)) || last) return;
  }
}

}  // namespace

void Lookahead::solve() {
  const bool ahead = solver_.concurrent();
  AxisPosition previous = solver_.words().home();  // the post starts from home too
  relay(parsed_, solved_, [&](AheadItem& item) {
    const auto* m = ahead ? std::get_if<cl::Motion>(&*item.record) : nullptr;
    if (!m || m->rotary_rad) return;
    AheadSolve s{m->point, previous, {}, {}};
    try {
      s.ik = solver_.solve_quiet(m->point, previous, solving_data_, &s.figures);
      if (s.ik.ok()) previous = *s.ik.position;
      item.solved = std::move(s);
    } catch (...) {
      // the post solves this motion itself and meets the same failure there
    }
  });
}

/// Each motion solved ahead, cut from the one solved before it (as solve() chains them).
void Lookahead::cut() {
  std::optional<SolvedPoint> before;
  relay(solved_, cut_, [&](AheadItem& item) {
    if (!item.solved || !item.solved->ik.ok()) return;  // (records that move nothing among them)
    const SolvedPoint to{item.solved->cl, *item.solved->ik.position, item.solved->ik.executed};
    const cl::Motion& m = std::get<cl::Motion>(*item.record);  // (only motions are solved ahead)
    if (before && before->q == item.solved->previous && (cut_rapids_ || !(m.rapid || m.from))) {
      try {
        item.cut = AheadCut{*before, to, (*cutter_)(*before, to, cutting_data_)};
      } catch (...) {
        // the post cuts this motion itself and meets the same failure there
      }
    }
    before = to;
  });
}

AheadItem Lookahead::next() {
  if (position_ == current_.size()) {
    std::optional<std::vector<AheadItem>> batch = cutter_ ? cut_.pop() : solved_.pop();
    if (!batch) return {};  // stopped: only while the object is being destroyed
    current_.clear();
    spare_.offer(std::move(current_));  // (to be filled again by the reading thread)
    current_ = std::move(*batch);
    position_ = 0;
  }
  return std::move(current_[position_++]);
}

}  // namespace ncpost::detail
