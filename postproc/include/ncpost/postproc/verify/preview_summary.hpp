// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the HTML report of `ncpost preview` shows, gathered block by block with bounded memory:
// totals, a log-scale histogram of the block errors, the error along the program and the tool
// path (XY of W) decimated to at most `max_points` buckets (pairs of buckets merge when full; a
// bucket keeps its largest error), and the `worst` blocks. Units: mm, rad; positions in W.
#include <cstddef>
#include <vector>

#include "ncpost/postproc/verify/preview_blocks.hpp"

namespace ncpost::preview {

class PreviewSummary {
 public:
  explicit PreviewSummary(std::size_t max_points = 2000, std::size_t worst = 10);
  void add(const BlockRow& row);

  struct SeriesBucket {
    std::size_t first_block = 0;
    std::size_t last_block = 0;
    double max_error_mm = 0.0;
    double max_harmonic_mm = 0.0;
  };
  struct PathBucket {
    Vec3d start_mm = Vec3d::Zero();
    Vec3d end_mm = Vec3d::Zero();
    double max_error_mm = 0.0;
  };
  /// Log-scale histogram: bin 0 holds errors below `histogram_floor_mm`, bin k >= 1 the errors in
  /// [floor·10^((k−1)/bins_per_decade), floor·10^(k/bins_per_decade)).
  static constexpr double histogram_floor_mm = 1e-6;
  static constexpr int bins_per_decade = 4;
  static constexpr int histogram_bins = 1 + 7 * bins_per_decade;  // up to 10 mm (last bin open)

  std::size_t blocks() const { return blocks_; }
  double max_error_mm() const { return max_error_; }
  double mean_error_mm() const { return blocks_ ? sum_error_ / static_cast<double>(blocks_) : 0.0; }
  double max_orientation_rad() const { return max_orientation_; }
  double max_harmonic_residual_mm() const { return max_residual_; }
  std::size_t blocks_over(double tolerance_mm) const;
  const std::vector<std::size_t>& histogram() const { return histogram_; }
  static double bin_lower_mm(int bin);
  std::vector<SeriesBucket> series() const;
  std::vector<PathBucket> path() const;
  /// The worst blocks, largest error first.
  const std::vector<BlockRow>& worst() const { return worst_; }

 private:
  void push_series(const SeriesBucket& b);
  void push_path(const PathBucket& b);

  std::size_t max_points_;
  std::size_t worst_count_;
  std::size_t blocks_ = 0;
  double max_error_ = 0.0, sum_error_ = 0.0, max_orientation_ = 0.0, max_residual_ = 0.0;
  std::vector<std::size_t> histogram_;
  std::vector<std::size_t> over_;  ///< counts over 1, 5, 10, 50, 100 um
  std::vector<SeriesBucket> series_;
  std::vector<PathBucket> path_;
  std::size_t stride_ = 1;      ///< blocks per bucket
  std::size_t path_limit_ = 0;  ///< path size that triggers a merge
  SeriesBucket open_series_;
  PathBucket open_path_;
  std::size_t open_count_ = 0;
  bool path_open_ = false;
  std::vector<BlockRow> worst_;
};

}  // namespace ncpost::preview
