#pragma once
// SPDX-License-Identifier: Apache-2.0
// The tests' own reading of the Sinumerik drilling cycles (for sinumerik_mini.hpp), independent of
// the product: the heights along the tool axis (Z of the plane, program unit) where the cycle's
// motions end, in order, from the sequences in the SINUMERIK 840D sl cycles manual:
//   CYCLE81/82(RTP,RFP,SDIS,DP,DPR[,DTB]): RFP+SDIS, the depth, RTP;
//   CYCLE85(...,DTB,FFR,RFF) and CYCLE86(...,DTB,SDIR,0,0,0,POSS): RFP+SDIS, the depth, RFP+SDIS, RTP;
//   CYCLE84 (rigid tapping) and CYCLE840 (compensating chuck): RFP+SDIS, the depth (tapping), RFP+SDIS
//     (the thread followed out), RTP;
//   CYCLE83(RTP,RFP,SDIS,DP,DPR,FDEP,FDPR,DAM,DTB,DTS,FRF,VARI,_AXN,_MDEP,_VRT,_DTD,_DIS1):
//     infeeds measured from RFP: the first to FDEP (or RFP-FDPR), each later one DAM shorter than the
//     one before but not shorter than DAM; while no more than twice DAM is left over, the last two
//     share what is left equally (DAM 0: every infeed as long as the first); VARI=1 goes out to
//     RFP+SDIS after each infeed and in again to the last bottom plus the anticipation distance
//     (_DIS1, or 0.6 for holes up to 30 deep, else depth/50 up to 7); VARI=0 backs off by _VRT (1).
// The depth: RFP-|DPR| where DPR is given and not 0, else DP.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace ncpost::test {

/// The numbers between the parentheses of a call; an empty argument is nullopt.
inline std::vector<std::optional<double>> sin_call_args(const std::string& line, std::size_t open) {
  std::vector<std::optional<double>> a;
  std::stringstream in(line.substr(open + 1, line.find(')', open) - open - 1));
  for (std::string s; std::getline(in, s, ',');) {
    s.erase(0, s.find_first_not_of(' '));
    a.push_back(s.empty() || s[0] == '"' ? std::nullopt : std::optional<double>(std::strtod(s.c_str(), nullptr)));
  }
  return a;
}

/// The infeed lengths of CYCLE83 from RFP, first `first` long, `total` in all, degression `dam`.
inline std::vector<double> cycle83_infeeds(double first, double total, double dam) {
  std::vector<double> feeds{std::min(first, total)};
  double done = feeds[0];
  while (total - done > 1e-9) {
    const double rest = total - done;
    const double next = dam > 0 ? std::max(feeds.back() - dam, dam) : feeds[0];
    const bool last_two = dam > 0 && next == dam && rest > dam && rest < 2 * dam;
    const std::vector<double> add = rest <= next ? std::vector<double>{rest}
                                    : last_two   ? std::vector<double>{rest / 2, rest / 2}
                                                 : std::vector<double>{next};
    for (double f : add) feeds.push_back(f), done += f;
  }
  return feeds;
}

/// Where along Z the cycle `name` (CYCLE81 ... CYCLE86, CYCLE840) with arguments `a` ends its motions.
inline std::vector<double> sinumerik_cycle_heights(const std::string& name,
                                                   const std::vector<std::optional<double>>& a) {
  const auto arg = [&](std::size_t i) { return i < a.size() && a[i] ? *a[i] : 0.0; };
  const double rtp = arg(0), rfp = arg(1), safe = rfp + std::abs(arg(2));
  const double bottom = arg(4) != 0 ? rfp - std::abs(arg(4)) : arg(3);
  if (name == "CYCLE81" || name == "CYCLE82") return {safe, bottom, rtp};
  if (name == "CYCLE85" || name == "CYCLE86" || name == "CYCLE84" || name == "CYCLE840")
    return {safe, bottom, safe, rtp};
  const double total = rfp - bottom;
  const double first = arg(6) != 0 ? std::abs(arg(6)) : a.size() > 5 && a[5] ? rfp - *a[5] : total;
  const std::vector<double> feeds = cycle83_infeeds(first, total, arg(7));
  const double back = arg(14) > 0 ? arg(14) : 1.0;
  const double ahead = arg(16) > 0 ? arg(16) : total <= 30 ? 0.6 : std::min(total / 50, 7.0);
  std::vector<double> h{safe};
  double z = rfp;
  for (std::size_t i = 0; i < feeds.size(); ++i) {
    z -= feeds[i];
    h.push_back(z);
    if (i + 1 == feeds.size()) break;
    if (arg(11) == 1) {
      h.push_back(safe);
      if (z + ahead < safe) h.push_back(z + ahead);
    } else {
      h.push_back(z + back);
    }
  }
  h.push_back(rtp);
  return h;
}

}  // namespace ncpost::test
