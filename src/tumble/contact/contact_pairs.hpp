#pragma once
// The pairs that contact_pair()'s table holds (contact_pair.hpp), one file each.
#include "tumble/contact/contact_pair.hpp"

namespace tumble {

const ContactPair& sphere_on_plane();      // sphere_on_plane.cpp
const ContactPair& round_on_plane();       // round_on_plane.cpp
const ContactPair& polyhedron_on_plane();  // polyhedron_on_plane.cpp

}  // namespace tumble
