#pragma once
// The line of two spheres' centres (a pair whose other surface is a sphere, or a shell touched
// from inside: pair_core.hpp), written over the scalar: a run's pairs take it in double
// (sphere_pairs.cpp), `tumble modes` in Dual, which differentiates it, so that both hold the same
// geometry. From the sphere's centre less the other's (apart_W) and its velocity less theirs
// (relative_velocity_W): the normal n, from the other's centre towards the sphere's, the centres'
// distance, and how fast n turns, (v - n (n . v)) / d. Inside a shell n and the distance are
// turned round (the normal runs from the centre towards the wall). turning is n' . v, what n's
// turning adds to the gap's second derivative: |v_t|^2 / d, never negative but inside a shell.
#include <cmath>

#include "tumble/math/types.hpp"

namespace tumble {

template <typename S>
struct SpherePairLineOf {
  Vec3Of<S> n_W = Vec3Of<S>::UnitZ();  // any where the centres coincide
  Vec3Of<S> n_rate_W = Vec3Of<S>::Zero();
  S distance = S(0.0);  // m (minus the centres' distance inside a shell)
  S turning = S(0.0);   // n' . v, m/s^2
};

template <typename S>
SpherePairLineOf<S> sphere_pair_line(const Vec3Of<S>& apart_W, const Vec3Of<S>& relative_velocity_W,
                                     bool touched_inside) {
  using std::sqrt;
  SpherePairLineOf<S> line;
  line.distance = sqrt(apart_W.squaredNorm());
  if (line.distance > 0.0) line.n_W = apart_W / line.distance;
  if (touched_inside) {
    line.distance = -line.distance;
    line.n_W = -line.n_W;
  }
  if (line.distance == 0.0) return line;
  const Vec3Of<S>& v_W = relative_velocity_W;
  const S along = line.n_W.dot(v_W);
  line.n_rate_W = (v_W - line.n_W * along) / line.distance;
  line.turning = (v_W.squaredNorm() - along * along) / line.distance;
  return line;
}

}  // namespace tumble
