// SPDX-License-Identifier: Apache-2.0
#pragma once
// Bounded series for reports: when a series of buckets outgrows its limit, neighbours merge in
// pairs (0 with 1, 2 with 3, ...; an odd last bucket stays as it is), halving its length. Used by
// the post's account (post_report.cpp) and the preview's summary (preview_summary.cpp).
#include <cstddef>
#include <utility>
#include <vector>

namespace ncpost::detail {

/// Halves `buckets`: each pair of neighbours becomes one, `merge(first, second)` folding the
/// second into the first.
template <class Bucket, class Merge>
void merge_pairs(std::vector<Bucket>& buckets, Merge merge) {
  std::vector<Bucket> merged;
  merged.reserve((buckets.size() + 1) / 2);
  for (std::size_t i = 0; i < buckets.size(); i += 2) {
    Bucket b = buckets[i];
    if (i + 1 < buckets.size()) merge(b, buckets[i + 1]);
    merged.push_back(std::move(b));
  }
  buckets = std::move(merged);
}

}  // namespace ncpost::detail
