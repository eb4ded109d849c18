#pragma once
// The interface between a mechanical system and the integrators: y' = f(t, y) on a state that may
// hold unit quaternions, with a projection back onto the manifold and the constraints after each
// step, located events (zero crossings of g_k(t, y)) that may make the state jump, and known
// breakpoints where the right-hand side is discontinuous. Free bodies use the first two; joints
// use project(), contact uses events and jumps, schedules and impulses use breakpoints.
#include <cstddef>
#include <limits>
#include <span>
#include <string>

#include "tumble/math/types.hpp"

namespace tumble {

class Formulation;  // dynamics/formulation.hpp

enum class EventDirection { Both, Rising, Falling };  // which sign changes of g count

// What the system asks for after it has seen a located event.
enum class EventAction {
  Record,  // nothing changes: the event is only reported (e.g. the prism's flip)
  Jump,    // on_event changed the state (an impact, a mode change): the method restarts there
  Stop,    // integration ends at the event
};

struct EventSpec {
  std::string name;
  EventDirection direction = EventDirection::Both;
  // Also an event where its function changes sign across a breakpoint's jump (a condition on the
  // state that an impulse makes true): it is then at the breakpoint's instant, after the jump.
  // The scenario's events are; a contact's mode changes are the breakpoint's own business.
  bool across_jumps = false;
};

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;

  virtual Eigen::Index dimension() const = 0;

  // Called by the driver once, before the first step from (t0, y). Systems whose right-hand side
  // has modes (loads switched on a schedule, contact modes) set the mode in force at t0 here.
  virtual void begin(double t0, const VecX& y);

  // y' = f(t, y). Called at every stage of every step: it must not allocate.
  virtual void derivative(double t, const VecX& y, VecX& dydt) const = 0;

  // Offsets in y of unit quaternions (w, x, y, z) whose derivative f gives as
  // q' = q (x) (0, omega_B) / 2. Vector-space methods integrate them as plain components and
  // rely on project(); Lie-group methods read omega_B back from q' and rotate exactly.
  // Contract: q' is linear in q and no other component of f depends on |q| (f uses the rotation
  // of q / |q|). So rescaling q rescales its four derivatives by the same factor and nothing
  // else: a method may renormalise q without evaluating f again.
  virtual std::span<const Eigen::Index> unit_quaternion_offsets() const { return {}; }

  // df/dy at (t, y) into dfdy (sized n x n by the caller), for the implicit methods (radau5);
  // returns false where the system gives none (the default). Called at the start of a step that
  // needs a new Jacobian (a method keeps one while its Newton iteration converges fast), never
  // inside a step's stages; it may allocate.
  virtual bool jacobian(double t, const VecX& y, MatX& dfdy) const;
  // Whether jacobian() gives one at all, in some modes at least (what `auto` asks at its start).
  virtual bool gives_jacobian() const { return false; }
  // Whether it gives one at (t, y) in the system's current modes (what `auto` asks before it
  // switches to radau5, and after each jump while radau5 runs); the default: gives_jacobian().
  virtual bool gives_jacobian_at(double /*t*/, const VecX& /*y*/) const { return gives_jacobian(); }

  // Put y back onto the manifold and the constraints after every accepted step and after every
  // jump. The default normalises the unit quaternions.
  virtual void project(double t, VecX& y) const;

  // Per component of y, the unit its absolute tolerance is given in, fixed from y0 when a method
  // starts (units sized to y0): atol_i = atol units_i. The default, 1 for every component: atol
  // is in the state's own units (m, m/s, rad/s, a quaternion's 1). A system whose components
  // scale with the problem (a work ledger's joules scale with the masses and with gravity) gives
  // them the problem's own scale, so that the same motion at any mass or gravity is held to the
  // same relative accuracy and takes the same steps. docs/integrators.md, "How the tolerances
  // are scaled".
  virtual void tolerance_units(const VecX& y0, VecX& units) const;

  // Located events. event_functions fills g (size events().size()).
  virtual std::span<const EventSpec> events() const { return {}; }
  virtual void event_functions(double t, const VecX& y, VecX& g) const;
  // Called at a located event with y at the event time; may change y.
  virtual EventAction on_event(std::size_t event_index, double t, VecX& y);
  // Called after each accepted step whose events are handled. A system whose event functions
  // watch something it updates step by step (a sliding contact watches the slip along the
  // direction it had at the step's start) updates it here and returns true; the driver then
  // evaluates g again.
  virtual bool refresh_event_functions(double t, const VecX& y);

  // The longest step (s) the method may take from (t, y), or +infinity: what the event functions
  // could not see from the ends of a longer step (a dip through zero and back) is kept out of
  // it. Adaptive methods honour it; fixed-step methods keep their step.
  virtual double step_limit(double t, const VecX& y) const;
  // Whether the last step_limit changed which event functions the system watches (a broad
  // phase's screening: one it no longer watches holds a constant, one it watches again has had
  // that constant): the driver then evaluates them at the step's start again.
  virtual bool events_rescreened() const { return false; }

  // The first time strictly after t at which f is discontinuous (a force switching on, an
  // impulse, a lock), or +infinity. The driver lands a step exactly on it, calls at_breakpoint
  // (which may change y, e.g. apply an impulse, and switches the mode of f), and restarts the
  // method. Between breakpoints f must not switch by itself: a step that ends on a breakpoint
  // evaluates its last stage AT the breakpoint and must see the mode of the interval before it.
  virtual double next_breakpoint(double t) const;
  virtual void at_breakpoint(double t, VecX& y);

  // The rigid-body formulation whose equations this system is: itself, or the one it runs with
  // more on top (the scenario's events); null for a system that is none. A method that does not
  // integrate f but evaluates the bodies' motion in closed form (`integrator: exact`) reads the
  // model and the state's layout (pack, unpack) from it.
  virtual const Formulation* rigid_body_formulation() const { return nullptr; }
};

// Normalises each unit quaternion of y in place.
void normalize_unit_quaternions(std::span<const Eigen::Index> offsets, VecX& y);

// After y_before became y_after: if they differ only by rescaled unit quaternions (as the default
// project() leaves them), rescale those slots of dydt = f(t, y_before) to make it f(t, y_after),
// by the contract above, and return true; otherwise return false (f must be evaluated again).
bool rescale_quaternion_derivatives(std::span<const Eigen::Index> offsets, const VecX& y_before,
                                    const VecX& y_after, VecX& dydt);

}  // namespace tumble
