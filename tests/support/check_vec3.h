//! 3-vector arithmetic for the independent checks in tests/ and bench/
//! (support/, corpus_check, decomposition_check, the unit tests' own
//! measures): difference, dot and cross products, length, unit vector, each
//! the plain expression component by component in the order written. Kept
//! apart from src/core/vec3_ops.h on purpose: a check must not share code
//! with what it checks. Header-only, no state.
#pragma once

#include <array>
#include <cmath>

namespace fabvdb::test {

using CheckVec3 = std::array<double, 3>;

inline CheckVec3 sub(const CheckVec3& a, const CheckVec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const CheckVec3& a, const CheckVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline CheckVec3 cross(const CheckVec3& a, const CheckVec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const CheckVec3& a) { return std::sqrt(dot(a, a)); }
//! `a` divided by its length (no guard: a zero vector gives NaNs).
inline CheckVec3 unit(const CheckVec3& a) {
    const double n = norm(a);
    return {a[0] / n, a[1] / n, a[2] / n};
}

}  // namespace fabvdb::test
