// SPDX-License-Identifier: Apache-2.0
#include "ncpost/kinematics/trr_xy_geometry.hpp"

#include <cassert>
#include <cmath>

namespace ncpost::trr {
namespace {

constexpr const char* kFields[kPerChain] = {"dr", "dt", "ar", "at", "ds", "gp", "dl", "drs", "dts", "dzs"};
constexpr const char kChains[3] = {'a', 'b', 'c'};

double ChainErrors::*field_ptr(int f) {
  static double ChainErrors::*const p[kPerChain] = {
      &ChainErrors::dr, &ChainErrors::dt, &ChainErrors::ar,  &ChainErrors::at,  &ChainErrors::ds,
      &ChainErrors::gp, &ChainErrors::dl, &ChainErrors::drs, &ChainErrors::dts, &ChainErrors::dzs};
  return p[f];
}

}  // namespace

double Geometry::pin_height_mm() const {
  const double dr = base_radius_mm - platform_radius_mm;
  return std::sqrt(link_length_mm * link_length_mm - dr * dr) + tip_offset_mm();
}

double& Errors::operator[](int k) {
  assert(k >= 0 && k < kParameterCount);
  return chain[static_cast<std::size_t>(k / kPerChain)].*field_ptr(k % kPerChain);
}

double Errors::operator[](int k) const {
  assert(k >= 0 && k < kParameterCount);
  return chain[static_cast<std::size_t>(k / kPerChain)].*field_ptr(k % kPerChain);
}

std::string Errors::name(int k) {
  assert(k >= 0 && k < kParameterCount);
  return std::string(kFields[k % kPerChain]) + "_" + kChains[k / kPerChain];
}

int Errors::index_of(const std::string& n) {
  for (int k = 0; k < kParameterCount; ++k)
    if (name(k) == n) return k;
  return -1;
}

bool Errors::is_angle(int k) {
  const int f = k % kPerChain;
  return f == 2 || f == 3 || f == 5;
}

bool Errors::all_zero() const {
  for (int k = 0; k < kParameterCount; ++k)
    if ((*this)[k] != 0.0) return false;
  return true;
}

Errors operator+(const Errors& a, const Errors& b) {
  Errors sum;
  for (int k = 0; k < kParameterCount; ++k) sum[k] = a[k] + b[k];
  return sum;
}

std::array<ChainFrame, 3> chain_frames(const Geometry& g, const Errors& e) {
  std::array<ChainFrame, 3> frames;
  const double H = g.pin_height_mm();
  for (std::size_t i = 0; i < 3; ++i) {
    const ChainErrors& ce = e.chain[i];
    const double theta = deg_to_rad(120.0 * static_cast<double>(i));
    ChainFrame& f = frames[i];
    f.radial = Vec3d(std::cos(theta), std::sin(theta), 0.0);
    f.tangential = Vec3d(-std::sin(theta), std::cos(theta), 0.0);
    f.pin_at_zero_mm = (g.base_radius_mm + ce.dr) * f.radial + ce.dt * f.tangential + Vec3d(0, 0, H);
    f.screw_down =
        rotation_about<double>(f.radial, -ce.at) * rotation_about<double>(f.tangential, ce.ar) * Vec3d::UnitZ();
    f.slider_zero_mm = ce.ds;
    f.pin_axis = rotation_about<double>(f.radial, ce.gp) * f.tangential;
    f.link_length_mm = g.link_length_mm + ce.dl;
    f.ball_in_plate_mm = (g.platform_radius_mm + ce.drs) * f.radial + ce.dts * f.tangential + ce.dzs * Vec3d::UnitZ();
  }
  return frames;
}

}  // namespace ncpost::trr
