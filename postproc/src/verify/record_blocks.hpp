// SPDX-License-Identifier: Apache-2.0
#pragma once
// The CL records that the serial post (post.cpp) and the TRR-XY post (trr_post.cpp) turn into NC
// blocks alike: the feed they keep (mm/min; a feed per revolution times the spindle speed), the
// spindle (speed and direction), coolant, comments and program stops. Motion, tool changes and
// cycles are each post's own.
#include <fmt/format.h>

#include <optional>
#include <string>

#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"

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
    restart_spindle_ = false;  // the program says what the spindle does after a stop
    spindle_turning_ = s.direction != cl::Spindle::Direction::off;
    if (!spindle_turning_) {
      writer_.spindle_stop();
      return;
    }
    if (s.rpm > 0.0) spindle_rpm_ = s.rpm;
    spindle_ccw_ = s.direction == cl::Spindle::Direction::ccw;
    writer_.spindle_on(spindle_rpm_, spindle_ccw_);
  }

  /// The dialect's coolant words (CoolantWords).
  void coolant(const cl::Coolant& c) {
    restart_coolant_ = false;
    coolant_on_.reset();
    if (c.on) coolant_on_ = c;
    write_coolant(c);
  }

  /// A program stop: the dialect's stop (or optional-stop) blocks, the operator's message as a
  /// comment on the last. M0/M1 stop the spindle and the coolant on many controls (Heidenhain
  /// always): the ones on before the stop start again before the next motion or dwell (`resume`),
  /// unless the program itself says what they do first.
  void stop(const cl::Stop& s) {
    const Dialect& d = writer_.dialect();
    const std::vector<std::string>& list = s.optional ? d.program_optional_stop : d.program_stop;
    for (std::size_t i = 0; i < list.size(); ++i) writer_.block(list[i], i + 1 == list.size() ? s.text : std::string());
    restart_spindle_ = spindle_turning_;
    restart_coolant_ = coolant_on_.has_value();
  }

  /// Before a motion or a dwell: the spindle and coolant that a stop may have turned off, on again.
  void resume() {
    if (restart_spindle_) writer_.spindle_on(spindle_rpm_, spindle_ccw_);
    if (restart_coolant_) write_coolant(*coolant_on_);
    restart_spindle_ = restart_coolant_ = false;
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
  void write_coolant(const cl::Coolant& c) {
    const CoolantWords& w = writer_.dialect().coolant;
    writer_.blocks(!c.on ? w.off : c.mode == "MIST" ? w.mist : w.flood);
  }

  NcWriter& writer_;
  double feed_mm_min_ = 0.0;
  bool given_ = false;
  double spindle_rpm_ = 0.0;
  bool spindle_ccw_ = false;
  bool spindle_turning_ = false;           ///< the last spindle record turns it
  std::optional<cl::Coolant> coolant_on_;  ///< the coolant in force (none: off)
  bool restart_spindle_ = false;           ///< a stop came since the spindle's last record
  bool restart_coolant_ = false;
};

}  // namespace ncpost::detail
