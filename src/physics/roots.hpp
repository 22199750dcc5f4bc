// Roots of the polynomials that give event times.
#pragma once

namespace breakshot {

/// Earliest time t in [0, t_max] at which the contact function
///   f(t) = c[0] + c[1] t + c[2] t^2 + ... + c[degree] t^degree
/// (positive while apart, negative while overlapping) is <= 0 while
/// decreasing: the moment of a collision. Returns +infinity if there is
/// none. Degree is at most 4. Rules that make event detection stable
/// (Bannerman et al. 2014):
/// - if f(0) <= 0 and f is decreasing at 0 the contact is now (t = 0);
/// - an overlap that is already opening (f increasing) is not a contact,
///   so the collision just handled is never found again;
/// - a grazing touch whose minimum dips below zero by any amount is
///   found; one that stays above zero is not.
/// The time returned is the first double at which f, evaluated exactly
/// from the given coefficients, is <= 0: at or just after the exact root
/// (within one ulp), never before it. t_max may be +infinity. Leading
/// zero coefficients lower the degree. Non-finite coefficients, a NaN or
/// negative t_max, or a degree outside 0..4 give +infinity.
double first_contact(const double* c, int degree, double t_max);

/// First contact for the ideal model: f(t) = c + 2 b t + a t^2 with
/// c = |dp|^2 - sigma^2, b = dp.dv, a = |dv|^2, in the stable form of
/// Bannerman et al. Returns +infinity if none.
double first_contact_quadratic(double c, double b, double a);

/// Real roots of a x^2 + b x + c = 0 in ascending order, computed
/// without cancellation. Returns the number of roots (0, 1 or 2); a double
/// root counts once, a == 0 solves the linear equation, and a == b == 0
/// (or non-finite input) gives none.
int solve_quadratic(double a, double b, double c, double roots[2]);

}  // namespace breakshot
