// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/preview_summary.hpp"

#include <algorithm>
#include <cmath>

#include "verify/pairwise_merge.hpp"

namespace ncpost::preview {
namespace {

constexpr double kOverThresholds[] = {0.001, 0.005, 0.01, 0.05, 0.1};

bool contiguous(const PreviewSummary::PathBucket& a, const PreviewSummary::PathBucket& b) {
  return (a.end_mm - b.start_mm).norm() < 1e-6;
}

}  // namespace

PreviewSummary::PreviewSummary(std::size_t max_points, std::size_t worst)
    : max_points_(std::max<std::size_t>(max_points, 16)),
      worst_count_(worst),
      histogram_(static_cast<std::size_t>(histogram_bins), 0),
      over_(std::size(kOverThresholds), 0),
      path_limit_(max_points_) {}

double PreviewSummary::bin_lower_mm(int bin) {
  return bin == 0 ? 0.0 : histogram_floor_mm * std::pow(10.0, static_cast<double>(bin - 1) / bins_per_decade);
}

std::size_t PreviewSummary::blocks_over(double tolerance_mm) const {
  for (std::size_t i = 0; i < std::size(kOverThresholds); ++i)
    if (std::abs(kOverThresholds[i] - tolerance_mm) < 1e-12) return over_[i];
  return 0;
}

void PreviewSummary::add(const BlockRow& row) {
  const double e = row.exact.max_error_mm;
  ++blocks_;
  max_error_ = std::max(max_error_, e);
  sum_error_ += e;
  max_orientation_ = std::max(max_orientation_, row.exact.max_orientation_rad);
  max_residual_ = std::max(max_residual_, row.harmonic_residual_mm);
  int bin = 0;
  if (e >= histogram_floor_mm)
    bin = std::min(histogram_bins - 1,
                   1 + static_cast<int>(std::floor(std::log10(e / histogram_floor_mm) * bins_per_decade)));
  ++histogram_[static_cast<std::size_t>(bin)];
  for (std::size_t i = 0; i < std::size(kOverThresholds); ++i)
    if (e > kOverThresholds[i]) ++over_[i];

  // series and path buckets of `stride_` blocks; a path bucket also ends at a discontinuity
  PathBucket p{row.cl.start.tip_mm, row.cl.end.tip_mm, e};
  if (path_open_ && !contiguous(open_path_, p)) {
    push_path(open_path_);
    path_open_ = false;
  }
  if (!path_open_) {
    open_path_ = p;
    path_open_ = true;
  } else {
    open_path_.end_mm = p.end_mm;
    open_path_.max_error_mm = std::max(open_path_.max_error_mm, e);
  }
  if (open_count_ == 0) open_series_ = {row.block, row.block, 0.0, 0.0};
  open_series_.last_block = row.block;
  open_series_.max_error_mm = std::max(open_series_.max_error_mm, e);
  open_series_.max_harmonic_mm = std::max(open_series_.max_harmonic_mm, row.harmonic_mm);
  if (++open_count_ >= stride_) {
    push_series(open_series_);
    push_path(open_path_);
    path_open_ = false;
    open_count_ = 0;
  }

  if (worst_count_ > 0 && (worst_.size() < worst_count_ || e > worst_.back().exact.max_error_mm)) {
    auto at = std::upper_bound(worst_.begin(), worst_.end(), e,
                               [](double v, const BlockRow& r) { return v > r.exact.max_error_mm; });
    worst_.insert(at, row);
    if (worst_.size() > worst_count_) worst_.pop_back();
  }
}

void PreviewSummary::push_series(const SeriesBucket& b) {
  series_.push_back(b);
  if (series_.size() < max_points_) return;
  detail::merge_pairs(series_, [](SeriesBucket& m, const SeriesBucket& next) {
    m.last_block = next.last_block;
    m.max_error_mm = std::max(m.max_error_mm, next.max_error_mm);
    m.max_harmonic_mm = std::max(m.max_harmonic_mm, next.max_harmonic_mm);
  });
  stride_ *= 2;
}

void PreviewSummary::push_path(const PathBucket& b) {
  path_.push_back(b);
  if (path_.size() < path_limit_) return;
  std::vector<PathBucket> merged;
  for (std::size_t i = 0; i < path_.size(); ++i) {
    PathBucket m = path_[i];
    if (i + 1 < path_.size() && contiguous(m, path_[i + 1])) {
      m.end_mm = path_[i + 1].end_mm;
      m.max_error_mm = std::max(m.max_error_mm, path_[i + 1].max_error_mm);
      ++i;
    }
    merged.push_back(m);
  }
  path_ = std::move(merged);
  path_limit_ = std::max(max_points_, 2 * path_.size());  // many discontinuities: grow, do not re-merge each time
}

std::vector<PreviewSummary::SeriesBucket> PreviewSummary::series() const {
  auto out = series_;
  if (open_count_ > 0) out.push_back(open_series_);
  return out;
}

std::vector<PreviewSummary::PathBucket> PreviewSummary::path() const {
  auto out = path_;
  if (path_open_) out.push_back(open_path_);
  return out;
}

}  // namespace ncpost::preview
