// SPDX-License-Identifier: Apache-2.0
// Sinumerik -> ISO blocks (the translator) -> CL records (the G-code reader), with every
// position mapped back to the Sinumerik line (sinumerik_reader.hpp).
#include "ncpost/postproc/read/sinumerik/sinumerik_reader.hpp"

#include <fmt/format.h>

#include <cctype>
#include <exception>
#include <iterator>
#include <map>
#include <streambuf>

#include "ncpost/machines/input_error.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"

namespace ncpost::sinumerik {
namespace {

/// The translator's ISO blocks as a character stream, one block a line; `source_line[i]` is the
/// Sinumerik line of ISO line i + 1.
class IsoStream final : public std::streambuf {
 public:
  explicit IsoStream(Translator& t) : translator_(t) {}
  std::vector<int> source_line;
  std::map<int, std::string> tool_selected;  ///< ISO line of a T word -> the tool's name ("" by number)
  /// The translator's own error (already on a Sinumerik line) and that line. The G-code reader,
  /// which reads ahead, first gets the blocks before it and an `M30` on its line, so that an error
  /// it finds on an earlier line is the one reported (SinumerikReader::next).
  std::exception_ptr failure;
  int failure_iso_line = 0;  ///< the line of that M30 among the ISO lines

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    buffer_.clear();
    if (failure) return traits_type::eof();
    IsoBlock b;
    try {
      for (int i = 0; i < 64 && translator_.next(b); ++i) {
        buffer_ += b.text;
        buffer_ += '\n';
        source_line.push_back(b.line);
        if (b.tool_name) tool_selected[static_cast<int>(source_line.size())] = *b.tool_name;
      }
    } catch (const InputError& e) {
      failure = std::current_exception();
      buffer_ += "M30\n";
      source_line.push_back(e.where().line);
      failure_iso_line = static_cast<int>(source_line.size());
    }
    if (buffer_.empty()) return traits_type::eof();
    setg(buffer_.data(), buffer_.data(), buffer_.data() + buffer_.size());
    return traits_type::to_int_type(*gptr());
  }

 private:
  Translator& translator_;
  std::string buffer_;
};

TranslatorOptions translator_options(const ReaderOptions& o) {
  TranslatorOptions t;
  t.arc_chord_tolerance_mm = o.arc_chord_tolerance_mm;
  t.max_call_depth = o.max_call_depth;
  t.max_blocks = o.max_blocks;
  t.block_skip = o.gcode.block_delete;
  return t;
}

}  // namespace

struct SinumerikReader::State {
  std::string file;
  Translator translator;
  IsoStream buffer;
  std::istream iso;
  gcode::GcodeClReader gcode;

  State(std::istream& in, std::string f, const Machine& m, const Setup& s, const ReaderOptions& o)
      : file(f),
        translator(load_program(in, f), m, s, translator_options(o)),
        buffer(translator),
        iso(&buffer),
        gcode((iso.exceptions(std::ios::badbit), iso), f, m, s, o.gcode) {}

  /// The Sinumerik line of ISO line `n` (0 when not known).
  int source_of(int n) const {
    return n >= 1 && static_cast<std::size_t>(n) <= buffer.source_line.size()
               ? buffer.source_line[static_cast<std::size_t>(n - 1)]
               : 0;
  }
  std::string text_of(int line) const {
    const auto& lines = translator.program().lines;
    return line >= 1 && static_cast<std::size_t>(line) <= lines.size() ? lines[static_cast<std::size_t>(line - 1)].text
                                                                       : "";
  }
  /// A tool change at ISO line `n` takes the name of the tool the last T word before it selected.
  void name_tool(cl::ToolChange& t, int n) const {
    auto it = buffer.tool_selected.upper_bound(n);
    if (it == buffer.tool_selected.begin() || std::prev(it)->second.empty()) return;
    t.name = std::prev(it)->second;
    t.number = 0;
  }
  /// "file:N[:C]: rest" with N an ISO line -> "file:M: rest" with M the Sinumerik line.
  std::string remap(const std::string& message) const {
    const std::string prefix = file + ":";
    if (message.rfind(prefix, 0) != 0) return message;
    std::size_t at = prefix.size(), end = at;
    while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
    if (end == at || end >= message.size() || message[end] != ':') return message;
    std::size_t rest = end + 1;
    std::size_t col = rest;
    while (col < message.size() && std::isdigit(static_cast<unsigned char>(message[col]))) ++col;
    if (col > rest && col < message.size() && message[col] == ':') rest = col + 1;
    const int iso_line = std::stoi(message.substr(at, end - at));
    return fmt::format("{}{}:{}", prefix, source_of(iso_line), message.substr(rest));
  }
};

SinumerikReader::SinumerikReader(std::istream& in, std::string file_name, const Machine& machine, const Setup& setup,
                                 ReaderOptions options)
    : state_(std::make_unique<State>(in, std::move(file_name), machine, setup, options)) {}

SinumerikReader::~SinumerikReader() = default;

std::optional<cl::Record> SinumerikReader::next() {
  State& s = *state_;
  // the translator's error, once the G-code reader reached its ISO line without an error of its own before it
  const auto after_failure = [&](int iso_line) {
    return s.buffer.failure && (iso_line == 0 || iso_line >= s.buffer.failure_iso_line);
  };
  std::optional<cl::Record> r;
  try {
    r = s.gcode.next();
  } catch (const InputError& e) {
    if (after_failure(e.where().line)) std::rethrow_exception(s.buffer.failure);
    const int line = s.source_of(e.where().line);
    throw InputError({s.file, line, 0}, e.detail(), s.text_of(line));
  } catch (const Infeasible& e) {
    throw Infeasible(s.remap(e.what()));
  }
  if (after_failure(r ? std::visit([](const auto& x) { return x.where.line; }, *r) : 0))  // (ISO line)
    std::rethrow_exception(s.buffer.failure);
  if (auto* t = r ? std::get_if<cl::ToolChange>(&*r) : nullptr) s.name_tool(*t, t->where.line);  // (ISO line)
  if (r) std::visit([&](auto& x) { x.where = cl::Location{s.source_of(x.where.line), 0}; }, *r);
  return r;
}

std::vector<std::string> SinumerikReader::take_notices() {
  std::vector<std::string> out = state_->translator.take_notices();
  for (std::string& n : state_->gcode.take_notices()) out.push_back(state_->remap(n));
  return out;
}

}  // namespace ncpost::sinumerik
