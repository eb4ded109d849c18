#pragma once
// Dual numbers: a value with its derivatives along any number of seeds (Eigen's forward-mode
// AutoDiffScalar). The physics written over a scalar type (math/types.hpp's Vec3Of, ...) is
// compiled for double, which a run integrates, and for Dual, which `tumble modes`
// differentiates: its Jacobians are then exact to round-off, with no step to choose.
#include <Eigen/Dense>
// After Eigen/Dense, which the AutoDiff module needs first.
#include <unsupported/Eigen/AutoDiff>

#include "tumble/math/types.hpp"
