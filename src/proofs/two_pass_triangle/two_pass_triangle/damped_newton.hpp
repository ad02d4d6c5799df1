// two_pass_triangle/damped_newton.hpp — the linear algebra of triangle_certify's dual search: one
// Newton step on the six coordinates x[c][i] (row-major 6 × 6 Hessian), in doubles. Only the search
// uses it; a step it gets wrong costs a certificate, never a wrong verdict (check_dual is exact).
#pragma once

#include <array>

namespace gsdot3::proofs::two_pass::triangle::certify {

// Solves H·d = −g on the coordinates of the free channels (free[c]: coordinates 2c and 2c + 1) by
// Cholesky with growing damping; d is 0 elsewhere. False if no damping up to 1 makes H positive definite.
bool newton_step(const std::array<bool, 3>& free, double* H, const double* g, double* d);

}  // namespace gsdot3::proofs::two_pass::triangle::certify
