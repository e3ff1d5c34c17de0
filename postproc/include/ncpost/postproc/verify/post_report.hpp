// SPDX-License-Identifier: Apache-2.0
#pragma once
// The before/after account of `ncpost post` (printed, and `--report FILE.html`): the program as it
// would be without `--model` and `--tolerance` (nominal commands, one block per CL motion) executed
// on the machine of the job — the model's machine, or the nominal one — against the written
// program re-executed on the same machine (`--verify`). Errors are contour errors: the distance of
// the executed tool tip from the straight CL segment of its block (mm, in W), per CL line.
// Memory stays bounded: the series along the program keep at most `max_points` buckets (the
// largest value of each).
#include <cstddef>
#include <string>
#include <vector>

#include "ncpost/postproc/verify/verify.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost {

/// Largest values of (x, y) pairs in at most `max_points` buckets of consecutive x.
class MaxSeries {
 public:
  explicit MaxSeries(std::size_t max_points = 1500) : max_points_(max_points) {}
  void add(double x, double y);
  std::vector<double> xs() const;
  std::vector<double> ys() const;

 private:
  struct Bucket {
    double x0, x1, y;
    std::size_t n;
  };
  void merge_pairs();
  std::size_t max_points_;
  std::size_t per_bucket_ = 1;
  std::vector<Bucket> buckets_;
};

/// The tool path for the 3D view of the report: the CL end point of every block of the "before"
/// program with its contour error, and the "after" error of the same CL lines (the largest of the
/// written blocks of a line). At most `max_points` points: beyond, neighbours merge (the later
/// point stays, the larger errors are kept), so memory stays bounded on any path.
class PathErrors {
 public:
  explicit PathErrors(std::size_t max_points = 20000) : max_points_(max_points) {}
  /// The written program re-executed: called in program order (CL lines rising).
  void add_after(int line, double contour_mm);
  /// The "before" program: one call per CL motion, in program order.
  void add_before(int line, const Vec3d& tip_mm, double contour_mm);

  struct Point {
    Vec3d tip_mm;
    int line_first, line_last;
    double before_mm, after_mm;  ///< after < 0: no written block re-executed for these lines
  };
  /// The points with their after errors.
  std::vector<Point> points() const;

 private:
  struct Span {
    int line_first, line_last;
    double value_mm;
  };
  std::size_t max_points_;
  std::vector<Point> before_;
  std::vector<Span> after_;
};

struct PostAccount {
  std::string input_name, machine_name, model_name, dialect_name, method_name;
  std::string executed_on;    ///< the machine both programs are executed on, in words
  double tolerance_mm = 0.0;  ///< 0: none
  std::size_t motions_in = 0, blocks_out = 0;
  // before: nominal program on the job's machine
  double before_max_mm = 0.0, before_mean_mm = 0.0;
  int before_worst_line = 0;
  std::size_t before_blocks = 0;
  double uncompensated_tip_max_mm = -1.0;  ///< tip error at the CL points (with a model; else < 0)
  double uncompensated_tip_rms_mm = 0.0;
  // after: the written program re-executed
  VerifyReport after;
  MaxSeries before_series, after_series;
  PathErrors path;
  /// Files named in the report with their SHA-256 (CL input, machine, model, verify-on model).
  std::vector<report::InputFile> inputs;
  std::vector<std::string> notices;
};

/// One line per figure, for the terminal.
std::string account_text(const PostAccount& a);

/// Self-contained HTML (inline SVG and the inline WebGL view of the path, no network): provenance
/// with the inputs' SHA-256, before/after figures in µm, the error along the program, and the
/// tool path in 3D coloured by the contour error before and after on one colour bar (µm).
std::string render_post_html(const PostAccount& a);

}  // namespace ncpost
