// SPDX-License-Identifier: MIT
// Physical constants and unit conversions used at the input border (SI inside the code).
#pragma once

namespace silodem {

inline constexpr double kPi = 3.14159265358979323846;
// Standard gravity used by the paper and by PHYSICS.md 2 (g = 9.81 m/s^2).
inline constexpr double kGravity = 9.81;

namespace units {
inline constexpr double mm = 1e-3;          // millimetre -> metre
inline constexpr double kPa = 1e3;          // kilopascal -> pascal
inline constexpr double deg = kPi / 180.0;  // degree -> radian
inline constexpr double percent = 1e-2;     // percent -> fraction
}  // namespace units

}  // namespace silodem
