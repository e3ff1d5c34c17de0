#include "lookahead.hpp"

#include <variant>

namespace ncpost::detail {

Lookahead::Lookahead(cl::Reader& reader, const MotionSolver& solver)
    : reader_(reader), solver_(solver), thread_([this] { run(); }) {}

Lookahead::~Lookahead() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

bool Lookahead::push(std::vector<AheadItem>&& batch) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return stop_ || ready_.size() < kMaxBatches; });
  if (stop_) return false;
  ready_.push_back(std::move(batch));
  lock.unlock();
  changed_.notify_all();
  return true;
}

void Lookahead::run() {
  AxisPosition previous{};  // the post starts from the zero position too
  std::vector<AheadItem> batch;
  batch.reserve(kBatchSize);
  for (;;) {
    AheadItem item;
    try {
      item.record = reader_.next();
      item.notices = reader_.take_notices();
    } catch (...) {
      item.record.reset();
      item.error = std::current_exception();
    }
    const bool last = !item.record;
    if (!last) {
      if (const auto* m = std::get_if<cl::Motion>(&*item.record); m && !m->rotary_rad) {
        AheadSolve s{m->point, previous, {}, {}};
        try {
          s.ik = solver_.solve_quiet(m->point, previous, &s.figures);
          if (s.ik.ok()) previous = *s.ik.position;
          item.solved = std::move(s);
        } catch (...) {
          // the post solves this motion itself and meets the same failure there
        }
      }
    }
    batch.push_back(std::move(item));
    if (last || batch.size() == kBatchSize) {
      if (!push(std::move(batch)) || last) return;  // push() sees a stop
      batch = {};
      batch.reserve(kBatchSize);
    }
  }
}

AheadItem Lookahead::next() {
  if (position_ == current_.size()) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !ready_.empty(); });
    current_ = std::move(ready_.front());
    ready_.pop_front();
    position_ = 0;
    lock.unlock();
    changed_.notify_all();
  }
  return std::move(current_[position_++]);
}

}  // namespace ncpost::detail
