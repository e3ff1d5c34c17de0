// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/nc_writer.hpp"

#include "ncpost/postproc/write/fixed_format.hpp"
#include "ncpost/postproc/write/nc_text.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace ncpost {

NcWriter::NcWriter(AtomicFile& out, Dialect dialect, std::string letters)
    : out_(out), dialect_(std::move(dialect)), letters_(std::move(letters)), line_number_(dialect_.numbers.start) {
  if (letters_.size() > static_cast<std::size_t>(kMaxAxes))
    throw std::invalid_argument(fmt::format("NcWriter: {} axis words ({}), more than the {} a block holds",
                                            letters_.size(), letters_, kMaxAxes));
}

double NcWriter::rounded(int axis, double value) const {
  const int decimals = axis < 3 ? dialect_.linear_decimals : dialect_.angle_decimals;
  static constexpr double kScale[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  const double scale = decimals >= 0 && decimals <= 9 ? kScale[decimals] : std::pow(10.0, decimals);
  const double r = std::round(value * scale) / scale;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

void NcWriter::start_line() {
  if (!dialect_.line_numbers) return;
  buf_.append(with_value(dialect_.numbers.format, "{n}", std::to_string(line_number_)));
  line_number_ += dialect_.numbers.step;
}

void NcWriter::end_line() {
  if (keep_last_line_) {  // the line is whole in the buffer: flush() runs only at a line's end
    std::size_t begin = buf_.size();
    while (begin > 0 && buf_[begin - 1] != '\n') --begin;
    last_line_.assign(buf_.data() + begin, buf_.size() - begin);
  }
  buf_.push_back('\n');
  ++lines_;
  if (buf_.size() > (1 << 16)) flush();
}

void NcWriter::flush() {
  out_.write(std::string_view(buf_.data(), buf_.size()));
  buf_.clear();
}

void NcWriter::comment(const std::string& text) {
  if (dialect_.numbers.comments) start_line();
  // every text from outside (file and machine names, PARTNO, PPRINT) arrives here: one sanitiser
  const std::string safe = nc_comment_text(text, dialect_);
  if (dialect_.comments == Dialect::Comments::semicolon)
    fmt::format_to(std::back_inserter(buf_), "; {}", safe);
  else
    fmt::format_to(std::back_inserter(buf_), "({})", safe);
  end_line();
}

void NcWriter::append_note(const std::string& note) {
  if (note.empty()) return;
  const std::string safe = nc_comment_text(note, dialect_);  // the sanitiser of comment()
  if (dialect_.comments == Dialect::Comments::semicolon)
    fmt::format_to(std::back_inserter(buf_), " ; {}", safe);
  else
    fmt::format_to(std::back_inserter(buf_), " ({})", safe);
}

void NcWriter::block(const std::string& words) {
  write_held("");
  write_block(words);
}

void NcWriter::block(const std::string& words, const std::string& note) {
  write_held("");
  if (active_cycle_ && words != dialect_.cycles->cancel) end_cycle();
  start_line();
  buf_.append(words);
  append_note(note);
  end_line();
}

void NcWriter::write_block(const std::string& words) {
  if (active_cycle_ && words != dialect_.cycles->cancel) end_cycle();
  start_line();
  buf_.append(words);
  end_line();
}

void NcWriter::blocks(const std::vector<std::string>& list) {
  for (const auto& words : list) block(words);
}

std::string NcWriter::rpm_text(double rpm) const { return rpm > 0.0 ? fmt::format("{:.0f}", rpm) : std::string(); }

/// `words` with "{rpm}" as `rpm`, or without the word that names it when `rpm` is empty.
static std::string with_rpm(const std::string& words, const std::string& rpm) {
  return rpm.empty() ? without_word(words, "{rpm}") : with_value(words, "{rpm}", rpm);
}

void NcWriter::write_held(const std::string& rpm) {
  if (!held_) return;
  const std::vector<std::string> held = std::move(*held_);
  held_.reset();
  const std::string speed = rpm.empty() ? rpm_text(spindle_rpm_) : rpm;
  for (const auto& words : held)
    if (const std::string b = with_rpm(words, speed); !b.empty()) write_block(b);
}

void NcWriter::tool_change(const std::vector<std::string>& list) {
  write_held("");
  // the changer moves the axes (Z to its change position at least, X Y on many machines): the
  // next motion writes every axis word and its motion word again, as the CAM's point says
  for (auto& v : last_) v.reset();
  last_motion_.reset();
  for (const auto& words : list)
    if (words.find("{rpm}") != std::string::npos) {
      held_ = list;
      return;
    }
  for (const auto& words : list) write_block(words);
}

void NcWriter::spindle_on(double rpm, bool counter_clockwise) {
  const SpindleWords& w = dialect_.spindle;
  if (rpm > 0.0) spindle_rpm_ = rpm;
  const std::string speed = rpm_text(spindle_rpm_);
  const std::vector<std::string>* list = &w.start;
  if (held_) {  // the speed goes into the tool call
    write_held(speed);
    list = &w.after_call;
  }
  for (const auto& words : *list) {
    const std::string b =
        with_rpm(with_value(words, "{turn}", counter_clockwise ? w.counter_clockwise : w.clockwise), speed);
    if (!b.empty()) write_block(b);
  }
}

void NcWriter::spindle_stop() { blocks(dialect_.spindle.stop); }

void NcWriter::spindle_turn(bool counter_clockwise) {
  block(counter_clockwise ? dialect_.spindle.counter_clockwise : dialect_.spindle.clockwise);
}

void NcWriter::begin_program(const std::string& name, const std::vector<std::string>& header_comments) {
  program_name_ = nc_program_name(name, dialect_);
  if (dialect_.percent_framing) {
    fmt::format_to(std::back_inserter(buf_), "%\n");
    ++lines_;
  }
  for (const auto& words : dialect_.program_start) {
    if (words == "{comments}") {
      for (const auto& c : header_comments) comment(c);
    } else {
      block(with_value(words, "{program}", program_name_));
    }
  }
}

void NcWriter::tool_blocks(const std::vector<std::string>& blocks, int tool, int length_register) {
  for (const auto& words : blocks) block(with_tool(words, tool, length_register));
}

void NcWriter::rtcp(bool on, int tool, int length_register) {
  tool_blocks(on ? dialect_.rtcp_on : dialect_.rtcp_off, tool, length_register);
}

bool NcWriter::moves_to(const NcMotion& m) const {
  for (std::size_t i = 0; i < word_count(); ++i)
    if (!last_[i] || *last_[i] != rounded(static_cast<int>(i), m.values[i])) return true;
  return false;
}

void NcWriter::append_motion_words(const NcMotion& m) {
  const MotionWords& w = dialect_.motion;
  const bool inverse = m.feed_mode == NcMotion::FeedMode::inverse_time;
  if (!m.rapid && (!last_feed_mode_ || *last_feed_mode_ != m.feed_mode)) {
    const std::string& mode = inverse ? w.inverse_time : w.per_minute;
    if (!mode.empty()) {
      buf_.append(mode);
      buf_.push_back(' ');
    }
    last_feed_mode_ = m.feed_mode;
    last_feed_.reset();
  }
  const int g = m.rapid ? 0 : 1;
  if (!w.modal || !last_motion_ || *last_motion_ != g) {
    buf_.append(m.rapid ? w.rapid : w.linear);
    last_motion_ = g;
  }
}

int NcWriter::append_axis_words(const NcMotion& m) {
  int words = 0;
  for (std::size_t i = 0; i < word_count(); ++i) {
    const double v = rounded(static_cast<int>(i), m.values[i]);
    if (last_[i] && *last_[i] == v) continue;
    if (buf_.size() && buf_[buf_.size() - 1] != ' ' && buf_[buf_.size() - 1] != '\n') buf_.push_back(' ');
    buf_.push_back(letters_[i]);
    append_fixed(buf_, v, i < 3 ? dialect_.linear_decimals : dialect_.angle_decimals, dialect_.motion.plus_sign);
    last_[i] = v;
    ++words;
  }
  return words;
}

void NcWriter::append_feed_word(const NcMotion& m) {
  const MotionWords& w = dialect_.motion;
  const bool inverse = m.feed_mode == NcMotion::FeedMode::inverse_time;
  if (m.rapid) {
    if (!w.rapid_feed.empty()) {
      buf_.push_back(' ');
      buf_.append(w.rapid_feed);
    }
  } else if (inverse || !w.feed_modal || !last_feed_ || std::abs(*last_feed_ - m.feed) > 1e-9) {
    buf_.push_back(' ');
    buf_.append(w.feed_letter);
    append_fixed(buf_, m.feed, inverse ? w.inverse_time_decimals : w.feed_decimals);
    last_feed_ = m.feed;
  }
}

bool NcWriter::motion(const NcMotion& m, const std::string& note) {
  write_held("");
  if (active_cycle_) {
    // the cancel word first if this motion writes a block (a move to where the tool is writes none)
    if (!moves_to(m)) return false;
    end_cycle();
  }
  const std::size_t line_start = buf_.size();
  const long number_before = line_number_;
  const auto saved_motion = last_motion_;
  const auto saved_mode = last_feed_mode_;
  const auto saved_feed = last_feed_;
  start_line();
  append_motion_words(m);
  if (append_axis_words(m) == 0) {  // the control is already there: no block
    buf_.resize(line_start);
    line_number_ = number_before;
    last_motion_ = saved_motion;
    last_feed_mode_ = saved_mode;
    last_feed_ = saved_feed;
    return false;
  }
  append_feed_word(m);
  append_note(note);
  end_line();
  ++blocks_;
  return true;
}

void NcWriter::arc(const NcArc& a) {
  write_held("");
  end_cycle();
  start_line();
  const ArcWords& words = *dialect_.arcs;  // the post writes arcs only in a dialect that has them
  const MotionWords& w = dialect_.motion;
  per_minute_mode();
  if (a.plane != plane_) {
    buf_.append(words.planes[static_cast<std::size_t>(a.plane == 17 ? 0 : a.plane == 18 ? 1 : 2)]);
    buf_.push_back(' ');
    plane_ = a.plane;
  }
  buf_.append(a.clockwise ? words.clockwise : words.counter_clockwise);
  last_motion_ = a.clockwise ? 2 : 3;
  for (std::size_t i = 0; i < 3; ++i) {
    const double v = rounded(static_cast<int>(i), a.end_mm[i]);
    buf_.push_back(' ');
    buf_.push_back(letters_[i]);
    append_fixed(buf_, v, dialect_.linear_decimals, w.plus_sign);
    last_[i] = v;
  }
  for (int i = 0; i < 3; ++i) {
    if ((a.plane == 17 && i == 2) || (a.plane == 18 && i == 1) || (a.plane == 19 && i == 0)) continue;
    buf_.push_back(' ');
    buf_.push_back(words.centre_letters[static_cast<std::size_t>(i)]);
    append_fixed(buf_, a.centre_offset_mm[static_cast<std::size_t>(i)], dialect_.linear_decimals, w.plus_sign);
  }
  if (!w.feed_modal || !last_feed_ || std::abs(*last_feed_ - a.feed_mm_min) > 1e-9) {
    buf_.push_back(' ');
    buf_.append(w.feed_letter);
    append_fixed(buf_, a.feed_mm_min, w.feed_decimals);
    last_feed_ = a.feed_mm_min;
  }
  end_line();
  ++blocks_;
}

bool NcWriter::continues(const NcCycle& c, double return_z_mm) const {
  if (!active_cycle_) return false;
  const NcCycle& a = *active_cycle_;
  if (a.code != c.code || a.retract_to_r != c.retract_to_r || a.words != c.words || a.before != c.before ||
      std::abs(a.feed_mm_min - c.feed_mm_min) > 1e-9)
    return false;
  if (rounded(2, return_z_mm) != cycle_return_z_) return false;
  // G99 travels at the R plane: only to a hole with the same R plane
  return !c.retract_to_r || rounded(2, c.r_plane_mm) == rounded(2, a.r_plane_mm);
}

void NcWriter::per_minute_mode() {
  if (last_feed_mode_ && *last_feed_mode_ == NcMotion::FeedMode::per_minute) return;
  if (!dialect_.motion.per_minute.empty()) {
    buf_.append(dialect_.motion.per_minute);
    buf_.push_back(' ');
  }
  last_feed_mode_ = NcMotion::FeedMode::per_minute;
  last_feed_.reset();
}

void NcWriter::end_cycle() {
  if (!active_cycle_) return;
  active_cycle_.reset();
  write_block(dialect_.cycles->cancel);
  last_motion_.reset();  // the next motion writes its G0/G1
}

void NcWriter::cycle(const NcCycle& c) {
  write_held("");
  const CycleWords& words = *dialect_.cycles;  // the post writes cycles only in a dialect that has them
  if (!continues(c, c.retract_to_r ? c.r_plane_mm : last_[2].value_or(c.r_plane_mm))) {
    end_cycle();
    for (const std::string& b : c.before) write_block(b);
    start_line();
    per_minute_mode();
    // the initial level of G98 is where the tool stands now
    cycle_return_z_ = c.retract_to_r ? rounded(2, c.r_plane_mm) : last_[2].value_or(rounded(2, c.r_plane_mm));
    fmt::format_to(std::back_inserter(buf_), "{} {}", c.retract_to_r ? words.return_r : words.return_initial, c.code);
    for (std::size_t i = 0; i < 3; ++i) {
      buf_.push_back(' ');
      buf_.push_back(letters_[i]);
      append_fixed(buf_, rounded(static_cast<int>(i), c.bottom_mm[i]), dialect_.linear_decimals);
    }
    buf_.append(std::string_view(" R"));
    append_fixed(buf_, rounded(2, c.r_plane_mm), dialect_.linear_decimals);
    buf_.append(c.words);
    buf_.push_back(' ');
    buf_.append(dialect_.motion.feed_letter);
    append_fixed(buf_, c.feed_mm_min, dialect_.motion.feed_decimals);
    last_feed_ = c.feed_mm_min;
    active_cycle_ = c;
  } else {
    // the next hole of the modal cycle: the words that change (X at least, so the block drills)
    start_line();
    const NcCycle& a = *active_cycle_;
    bool any = false;
    for (std::size_t i = 0; i < 3; ++i) {
      const double v = rounded(static_cast<int>(i), c.bottom_mm[i]);
      const double before = i < 2 ? *last_[i] : rounded(2, a.bottom_mm[2]);
      if (v == before && !(i == 1 && !any)) continue;
      if (any) buf_.push_back(' ');
      buf_.push_back(letters_[i]);
      append_fixed(buf_, v, dialect_.linear_decimals);
      any = true;
    }
    if (rounded(2, c.r_plane_mm) != rounded(2, a.r_plane_mm)) {
      buf_.append(std::string_view(" R"));
      append_fixed(buf_, rounded(2, c.r_plane_mm), dialect_.linear_decimals);
    }
    active_cycle_ = c;
  }
  end_line();
  ++blocks_;
  last_motion_.reset();
  last_[0] = rounded(0, c.bottom_mm[0]);
  last_[1] = rounded(1, c.bottom_mm[1]);
  last_[2] = cycle_return_z_;
}

void NcWriter::tilted_plane(const std::vector<std::string>& blocks, bool on) {
  end_cycle();
  for (const auto& words : blocks) block(words);
  tilted_ = on;
  // the plane's coordinates (or, after it, the program frame's) start afresh: every word is written
  for (auto& v : last_) v.reset();
  last_motion_.reset();
}

std::string NcWriter::word_value(int axis, double value) const {
  fmt::memory_buffer b;
  append_fixed(b, rounded(axis, value), axis < 3 ? dialect_.linear_decimals : dialect_.angle_decimals,
               dialect_.motion.plus_sign);
  return fmt::to_string(b);
}

namespace {

/// True when `words` hold an axis word (a letter of X Y Z A B C U V W and a number) for an axis
/// that is not one of `letters` (the end's `G91 G28 Z0` on a machine without Z).
bool names_missing_axis(const std::string& words, const std::string& letters) {
  std::size_t at = 0;
  while (at < words.size()) {
    const std::size_t end = std::min(words.find(' ', at), words.size());
    const std::string word = words.substr(at, end - at);
    at = end + 1;
    if (word.size() < 2 || std::string("XYZABCUVW").find(word[0]) == std::string::npos) continue;
    if (word.find_first_not_of("+-.0123456789", 1) != std::string::npos) continue;
    if (letters.find(word[0]) == std::string::npos) return true;
  }
  return false;
}

}  // namespace

void NcWriter::end_program() {
  write_held("");
  end_cycle();
  for (const auto& words : dialect_.program_end)
    if (!names_missing_axis(words, letters_)) write_block(with_value(words, "{program}", program_name_));
  if (dialect_.percent_framing) fmt::format_to(std::back_inserter(buf_), "%\n");
  flush();
}

}  // namespace ncpost

namespace ncpost {

WrittenState NcWriter::in_force() const {
  WrittenState s;
  s.values = last_;
  if (last_motion_)
    s.motion = *last_motion_ == 0   ? WrittenState::Motion::rapid
               : *last_motion_ == 1 ? WrittenState::Motion::linear
               : *last_motion_ == 2 ? WrittenState::Motion::clockwise
                                    : WrittenState::Motion::counter_clockwise;
  s.plane = plane_;
  s.inverse_time = last_feed_mode_ && *last_feed_mode_ == NcMotion::FeedMode::inverse_time;
  s.feed = last_feed_;
  return s;
}

}  // namespace ncpost
