// SPDX-License-Identifier: Apache-2.0
#pragma once
// The CL records that the serial post (post.cpp) and the TRR-XY post (trr_post.cpp) turn into NC
// blocks alike: the feed they keep (mm/min; a feed per revolution times the spindle speed), the
// spindle (speed and direction), coolant and comments. Motion, tool changes and cycles are each
// post's own.
#include <fmt/format.h>

#include <optional>
#include <string>

#include "ncpost/postproc/cl_record.hpp"
#include "ncpost/postproc/nc_writer.hpp"

namespace ncpost::detail {

class RecordBlocks {
 public:
  explicit RecordBlocks(NcWriter& writer) : writer_(writer) {}

  /// Takes a FEDRAT. Returns the notice to give when a feed per revolution comes before any
  /// spindle speed (it is then taken as mm/min).
  std::optional<std::string> feed(const cl::Feed& f) {
    std::optional<std::string> notice;
    if (f.per_rev && spindle_rpm_ <= 0.0) notice = "feed per revolution before a spindle speed: taken as mm/min";
    feed_mm_min_ = f.per_rev && spindle_rpm_ > 0.0 ? f.value * spindle_rpm_ : f.value;
    given_ = true;
    return notice;
  }

  /// The dialect's spindle words (SpindleWords; a held tool call takes the speed).
  void spindle(const cl::Spindle& s) {
    if (s.direction == cl::Spindle::Direction::off) {
      writer_.spindle_stop();
      return;
    }
    if (s.rpm > 0.0) spindle_rpm_ = s.rpm;
    spindle_ccw_ = s.direction == cl::Spindle::Direction::ccw;
    writer_.spindle_on(spindle_rpm_, spindle_ccw_);
  }

  /// The dialect's coolant words (CoolantWords).
  void coolant(const cl::Coolant& c) {
    const CoolantWords& w = writer_.dialect().coolant;
    writer_.blocks(!c.on ? w.off : c.mode == "MIST" ? w.mist : w.flood);
  }
  void comment(const cl::Comment& c) {
    if (!c.text.empty()) writer_.comment(c.text);
  }
  void unsupported(const cl::Unsupported& u) { writer_.comment(u.text); }

  bool feed_given() const { return given_; }
  double spindle_rpm() const { return spindle_rpm_; }  ///< 0 before any speed
  bool spindle_ccw() const { return spindle_ccw_; }
  /// The feed in force (mm/min), or `fallback` before any FEDRAT.
  double feed_mm_min(double fallback) const { return given_ ? feed_mm_min_ : fallback; }

  /// The feed state, to set another for a while (a cycle's own feed) and put it back.
  struct Saved {
    double feed_mm_min;
    bool given;
  };
  Saved save() const { return {feed_mm_min_, given_}; }
  void set_feed(double mm_min) {
    feed_mm_min_ = mm_min;
    given_ = true;
  }
  void restore(const Saved& s) {
    feed_mm_min_ = s.feed_mm_min;
    given_ = s.given;
  }

 private:
  NcWriter& writer_;
  double feed_mm_min_ = 0.0;
  bool given_ = false;
  double spindle_rpm_ = 0.0;
  bool spindle_ccw_ = false;
};

}  // namespace ncpost::detail
