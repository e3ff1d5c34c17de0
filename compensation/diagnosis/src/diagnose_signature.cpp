// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_signature.hpp"

#include <Eigen/QR>
#include <cmath>
#include <algorithm>
#include <set>

namespace ncpost::comp {
namespace {

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size();
  if (n < 3) return 0.0;
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
  ma /= double(n), mb /= double(n);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

/// Residual of value v of every row of a set (µm).
std::vector<double> column_um(const MeasurementSet& s, const Eigen::VectorXd& r, Eigen::Index at, int v) {
  const int n = s.values_per_row();
  std::vector<double> out(s.rows.size());
  for (std::size_t k = 0; k < s.rows.size(); ++k) out[k] = 1e3 * r[at + static_cast<Eigen::Index>(k) * n + v];
  return out;
}

}  // namespace

std::string value_name(const MeasurementSet& set, int value) {
  switch (set.type) {
    case MeasurementType::ballbar:
      return "L";
    case MeasurementType::sphere:
      return std::string("d") + char('x' + value);
    case MeasurementType::laser:
      return "e_um";
  }
  return "?";
}

ResidualSignature residual_signature(const Machine& m, const std::vector<MeasurementSet>& sets,
                                     const Eigen::VectorXd& r) {
  ResidualSignature sig;
  Eigen::Index at = 0;
  for (const auto& s : sets) {
    const int nv = s.values_per_row();
    const std::size_t rows = s.rows.size();
    for (int v = 0; v < nv; ++v) {
      const std::vector<double> y = column_um(s, r, at, v);
      // spectrum against each rotary angle
      for (int k = 0; k < m.rotary_count(); ++k) {
        const int index = 3 + k;
        std::set<long long> distinct;
        double lo = 1e300, hi = -1e300;
        for (const auto& row : s.rows) {
          distinct.insert(std::llround(row.command[index] * 1e6));
          lo = std::min(lo, row.command[index]);
          hi = std::max(hi, row.command[index]);
        }
        // harmonics separate only over (nearly) a full turn
        if (distinct.size() < 9 || hi - lo < 1.5 * kPi) continue;
        Eigen::MatrixXd A(static_cast<Eigen::Index>(rows), 9);
        Eigen::VectorXd b(static_cast<Eigen::Index>(rows));
        for (std::size_t i = 0; i < rows; ++i) {
          const double q = s.rows[i].command[index];
          const Eigen::Index ii = static_cast<Eigen::Index>(i);
          A(ii, 0) = 1.0;
          for (int h = 1; h <= 4; ++h) {
            A(ii, 2 * h - 1) = std::cos(h * q);
            A(ii, 2 * h) = std::sin(h * q);
          }
          b[ii] = y[i];
        }
        const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
        SpectrumLine line{s.file, v, m.axes[static_cast<std::size_t>(index)].letter, {}};
        for (int h = 1; h <= 4; ++h)
          line.amplitude_um[static_cast<std::size_t>(h - 1)] = std::hypot(c[2 * h - 1], c[2 * h]);
        sig.spectrum.push_back(line);
      }
      // direction of the last motion of each axis
      for (std::size_t index = 0; index < m.axes.size(); ++index) {
        std::vector<double> d(rows, 1.0);
        bool up = false, down = false;
        for (std::size_t i = 1; i < rows; ++i) {
          const double step =
              s.rows[i].command[static_cast<int>(index)] - s.rows[i - 1].command[static_cast<int>(index)];
          d[i] = step > 1e-12 ? 1.0 : step < -1e-12 ? -1.0 : d[i - 1];
          up = up || step > 1e-12;
          down = down || step < -1e-12;
        }
        if (!up || !down) continue;
        double fall = 0, rise = 0;
        int nf = 0, nr = 0;
        for (std::size_t i = 0; i < rows; ++i) (d[i] < 0 ? (fall += y[i], ++nf) : (rise += y[i], ++nr));
        DirectionLine line{s.file, v, m.axes[index].letter, pearson(y, d), 0.0};
        if (nf > 0 && nr > 0) line.falling_minus_rising_um = fall / nf - rise / nr;
        sig.reversal.push_back(line);
      }
      // time
      std::vector<double> t(rows);
      for (std::size_t i = 0; i < rows; ++i) t[i] = s.rows[i].time_s;
      TimeLine tl{s.file, v, pearson(y, t), 0.0};
      double mt = 0, my = 0;
      for (std::size_t i = 0; i < rows; ++i) mt += t[i], my += y[i];
      if (rows > 1) {
        mt /= double(rows), my /= double(rows);
        double sty = 0, stt = 0;
        for (std::size_t i = 0; i < rows; ++i) sty += (t[i] - mt) * (y[i] - my), stt += (t[i] - mt) * (t[i] - mt);
        if (stt > 0) tl.slope_um_per_h = 3600.0 * sty / stt;
      }
      sig.time.push_back(tl);
    }
    at += static_cast<Eigen::Index>(rows) * nv;
  }
  return sig;
}

double noise_from_differences_um(const std::vector<MeasurementSet>& sets, const Eigen::VectorXd& r) {
  double sum = 0.0;
  long long count = 0;
  Eigen::Index at = 0;
  for (const auto& s : sets) {
    const int nv = s.values_per_row();
    if (s.type != MeasurementType::sphere)
      for (std::size_t k = 1; k < s.rows.size(); ++k) {
        if (s.type == MeasurementType::laser && s.rows[k].run != s.rows[k - 1].run) continue;
        const double d = r[at + static_cast<Eigen::Index>(k)] - r[at + static_cast<Eigen::Index>(k) - 1];
        sum += d * d;
        ++count;
      }
    at += static_cast<Eigen::Index>(s.rows.size()) * nv;
  }
  if (count > 10) return 1e3 * std::sqrt(sum / (2.0 * double(count)));
  return r.size() ? 1e3 * std::sqrt(r.squaredNorm() / double(r.size())) : 0.0;
}

}  // namespace ncpost::comp
