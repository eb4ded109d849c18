#pragma once
// The Jacobian df/dy of a run's state equations (ArticulatedFormulation's y' = f(t, y)), for the
// implicit methods (integrators/radau5.hpp), by automatic differentiation of the one physics:
// the same equations `tumble modes` linearises (ModalEquations::rates over Dual), written about
// the state y in the modal coordinates z (modal_coordinates.hpp), then taken to the state's own
// coordinates joint by joint (JointKind::add_modal_tangent, add_modal_curvature):
//     df/dy = (E (dz'/dz) + C) P,   E = dy/dz, P = dz/dy (P E = I), C = (d^2 y / dz^2)[., z'],
// C from f = E(z) z' differentiated: a free body's speeds are kept in its turning axes.
// So it has what the modal equations hold: gravity, the loads and motors in force at t, springs
// and dampers, the loops' constraints (the motion on their manifold), the contacts in their
// modes. Joints held or driven at t
// have no modal coordinates: their rows and columns are zero, as are the work ledger's (nothing
// depends on the books). A quaternion's direction off the unit sphere, which the projection
// removes, has none either. Differences from the exact df/dy there only slow Newton's
// convergence; they do not change what the method converges to.
//
// Each call builds the modal equations about y (it allocates: an implicit method takes a
// Jacobian at the start of a step, and keeps it while Newton converges fast).
#include <memory>
#include <span>

#include "tumble/contact/contact_hold.hpp"
#include "tumble/math/types.hpp"
#include "tumble/modes/modal_coordinates.hpp"
#include "tumble/multibody/articulated_model.hpp"

namespace tumble {

// How the state y moves with the modal coordinates of `layout` about it: E = dy/dz and
// P = dz/dy (sized y.size() x layout.size() and back), joint by joint.
void calc_modal_tangent(const ArticulatedModel& model, const ModalLayout& layout, const VecX& y,
                        MatX& E, MatX& P);

// df/dy at (t, y) into dfdy (sized to y's dimension by the caller); t is the schedule's time
// (which loads, motors and holds are in force), `holds` how the contacts hold their bodies in
// the run's modes (one per contact: contact/contact_hold.hpp; empty without contacts): rolling or
// sticking at a point, or sliding at one with Coulomb's friction, whose direction the slip's
// velocity turns (the stiff part of a slip just grown from none), or on two or three points of
// the body (an edge's or a side's ends, a face's corners), each as a point is. Returns true.
// ArticulatedFormulation::set_state_jacobian takes it (the
// simulation layer hands it over: the formulation does not depend on this layer).
bool calc_state_jacobian(const std::shared_ptr<const ArticulatedModel>& model, double t,
                         const VecX& y, std::span<const ContactHold> holds, MatX& dfdy);

}  // namespace tumble
