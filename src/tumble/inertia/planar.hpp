#pragma once
// Planar (2D) moments of inertia about the axis normal to the plane, for the laminae and rod
// frames of the chapter's 2D examples: I_Gzz = int mu |d|^2 dA, and the planar parallel axis
// theorem I_O = I_G + M |c|^2.
namespace tumble::planar {

double rod_about_center(double mass, double length);         // M L^2 / 12
double ring_about_center(double mass, double radius);        // M R^2
double disk_about_center(double mass, double radius);        // M R^2 / 2
double plate_about_center(double mass, double a, double b);  // M (a^2 + b^2) / 12
// Square frame of four rods of side L and total mass M, about its centre: M L^2 / 3.
double square_frame_about_center(double mass, double side);
double parallel_axis(double inertia_about_com, double mass, double distance);  // I_G + M d^2

}  // namespace tumble::planar
