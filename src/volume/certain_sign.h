//! The floating-point filter in front of exact predicates: the sign of an
//! expression computed in doubles when it is certain, 0 when it is not. The
//! caller passes the square of the bound of the expression's terms (for a dot
//! of a cross product with a vector, the product of the three squared
//! lengths); a sign is returned only when |x| exceeds 1e-12 × that bound, far
//! above the rounding error of such expressions (~10 ulp of the bound), so a
//! nonzero answer is the sign exact arithmetic gives. Header-only, no state.
#pragma once

namespace fabvdb::volume {

//! The relative bound, squared, below which a sign is not trusted.
constexpr double filter_bound_squared = 1e-24;

//! 1 or -1 when x is certainly positive or negative, given the square
//! `bound_squared` of the bound on its terms; 0 when not sure.
inline int certain_sign(double x, double bound_squared) {
    if (x * x <= filter_bound_squared * bound_squared) return 0;
    return x > 0.0 ? 1 : -1;
}

}  // namespace fabvdb::volume
