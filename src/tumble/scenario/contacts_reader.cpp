// `contacts:`: a list of {type: plane, body:, plane: {point:, normal:}, friction:, restitution:}
// and {type: bodies, bodies: [a, b], friction:, restitution:}. On a plane the body must be of a
// shape whose contact with a plane tumble resolves: a sphere or shell, a round body (disk, ring,
// torus, cylinder, tube, cone, capsule) or a polyhedron (docs/scenario.md, Contacts), or a
// composite whose touching parts are (each a contact of its own). Two bodies touch at a sphere (or
// shell) and a sphere, a capsule, a box, a cylinder, a tube, a disk, a ring, a torus or a cone,
// or at two capsules (each a body's shape or a composite's part: each pair of parts a contact of
// its own).
#include <fmt/format.h>
#include <algorithm>
#include <deque>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

// The shapes that touch a plane, alone or as a composite's part (a part's sphere centre,
// polyhedron vertices and round axes and centre are placed in the body like any point and
// direction of it): all but a rod and a point.
bool touches_a_plane(ShapeKind kind) {
  return kind == ShapeKind::Sphere || kind == ShapeKind::Shell || kind == ShapeKind::Disk ||
         kind == ShapeKind::Ring || kind == ShapeKind::Cylinder || kind == ShapeKind::Tube ||
         kind == ShapeKind::Cone || kind == ShapeKind::Box || kind == ShapeKind::Plate ||
         kind == ShapeKind::Mesh || kind == ShapeKind::Torus || kind == ShapeKind::Capsule;
}

// As the messages name them.
constexpr const char* kTouchingShapes =
    "a sphere, shell, disk, ring, torus, cylinder, tube, cone, capsule, box, plate or mesh";

// The composite's parts that touch a plane, each a contact of its own: the one `part:` names, the
// list it names, or without it every part that can (one part hands over to another as the body
// turns: the new one's touchdown and the old one's lift-off are each a located event).
std::vector<int> read_touching_parts(const Reader& reader, const MapReader& map,
                                     const Field& body_field, const BodySpec& body) {
  const auto touching_names = [&] {
    std::string names;
    for (const PartSpec& part : body.parts) {
      if (!touches_a_plane(part.shape.kind)) continue;
      names += (names.empty() ? "" : ", ") + part.name;
    }
    return names.empty() ? std::string("none") : names;
  };
  std::vector<int> found;
  if (const auto f = map.find("part")) {
    const std::vector<Field> named =
        f->node.IsSequence() ? reader.items(*f, "of parts' names") : std::vector<Field>{*f};
    if (named.empty()) {
      reader.fail_at_value(
          *f, "name at least one part; those that can touch a plane: " + touching_names());
    }
    for (const Field& item : named) {
      const std::string name = reader.text(item);
      const auto at = std::find_if(body.parts.begin(), body.parts.end(),
                                   [&](const PartSpec& part) { return part.name == name; });
      if (at == body.parts.end()) {
        reader.fail_at_value(item, "body '" + body.name + "' has no part '" + name +
                                       "'; its parts that can touch a plane: " + touching_names());
      }
      if (!touches_a_plane(at->shape.kind)) {
        reader.fail_at_value(item, "part '" + name + "' of body '" + body.name + "' is a " +
                                       std::string(shape_name(at->shape.kind)) +
                                       "; of a composite's parts " + kTouchingShapes +
                                       " touches a plane; those that can: " + touching_names());
      }
      const int p = static_cast<int>(at - body.parts.begin());
      if (std::find(found.begin(), found.end(), p) != found.end()) {
        reader.fail_at_value(item, "part '" + name + "' named twice");
      }
      found.push_back(p);
    }
    return found;
  }
  for (std::size_t p = 0; p < body.parts.size(); ++p) {
    if (touches_a_plane(body.parts[p].shape.kind)) found.push_back(static_cast<int>(p));
  }
  if (found.empty()) {
    reader.fail_at_value(body_field, "body '" + body.name +
                                         "' is a composite; none of its parts can touch a plane "
                                         "(of a composite's parts " +
                                         kTouchingShapes + " touches)");
  }
  return found;
}

// The suffix a composite's part gives its contact's name where the contact is one of several,
// one per part (NAME_SUFFIX): the part's name, or partK for the unnamed parts[K].
std::string part_suffix(const BodySpec& body, int part) {
  const std::string& name = body.parts[static_cast<std::size_t>(part)].name;
  return name.rfind("parts[", 0) == 0 ? "part" + std::to_string(part) : name;
}

// Whether the shape touches another body's: a sphere's or a shell's surface, or a capsule's, a
// box's, a cylinder's, a tube's, a disk's, a ring's, a torus's or a cone's (which touch a sphere).
// A composite touches with its one part of the first four; only where it has none, with its one
// part of the others (so that a wheel or an axle beside a sphere part leaves that sphere its one
// part that touches).
bool is_sphere_or_shell(ShapeKind kind) {
  return kind == ShapeKind::Sphere || kind == ShapeKind::Shell;
}
bool touches_first(ShapeKind kind) {
  return is_sphere_or_shell(kind) || kind == ShapeKind::Capsule || kind == ShapeKind::Box;
}
bool touches_a_body(ShapeKind kind) {
  return touches_first(kind) || kind == ShapeKind::Cylinder || kind == ShapeKind::Disk ||
         kind == ShapeKind::Ring || kind == ShapeKind::Torus || kind == ShapeKind::Tube ||
         kind == ShapeKind::Cone;
}

// One of the two bodies of a `type: bodies` contact, or one of a composite's parts that touch:
// the part (-1: the body itself), its shape, whether that is a sphere (else a capsule, a box, a
// cylinder, a tube, a disk, a ring, a torus or a cone), and what it adds to the contact's name
// where the composite has several (the part's).
struct TouchingShape {
  int part = -1;
  ShapeKind kind = ShapeKind::Sphere;
  std::string suffix;
  bool sphere() const { return is_sphere_or_shell(kind); }
};
// Whether two shapes touch each other: where one is a sphere (or shell), or both are capsules.
bool touch_each_other(const TouchingShape& a, const TouchingShape& b) {
  return a.sphere() || b.sphere() || (a.kind == ShapeKind::Capsule && b.kind == ShapeKind::Capsule);
}
// The body's shape, or a composite's parts that touch another body: its sphere, shell, capsule and
// box parts, or where it has none of those its cylinder, tube, disk, ring, torus and cone parts
// (so that a wheel or an axle beside a sphere part leaves that sphere the part that touches).
std::vector<TouchingShape> read_touching_shapes(const Reader& reader, const Field& body_field,
                                                const BodySpec& body) {
  const char* what =
      "two bodies touch at a sphere (or shell) and a sphere, a capsule, a box, a cylinder, a "
      "tube, a disk, a ring, a torus or a cone, or at two capsules, each a body's shape (or a "
      "composite's sphere, shell, capsule or box parts, or where it has none of those its "
      "cylinder, tube, disk, ring, torus or cone parts)";
  if (body.parts.empty()) {
    if (touches_a_body(body.shape.kind)) return {{-1, body.shape.kind, ""}};
    reader.fail_at_value(body_field, "body '" + body.name + "' is a " +
                                         std::string(shape_name(body.shape.kind)) + "; " + what);
  }
  for (const bool first : {true, false}) {
    std::vector<TouchingShape> found;
    for (std::size_t p = 0; p < body.parts.size(); ++p) {
      const ShapeKind kind = body.parts[p].shape.kind;
      if (first ? !touches_first(kind) : !touches_a_body(kind)) continue;
      found.push_back({static_cast<int>(p), kind, part_suffix(body, static_cast<int>(p))});
    }
    if (found.size() == 1) found.front().suffix.clear();
    if (!found.empty()) return found;
  }
  reader.fail_at_value(body_field, "body '" + body.name +
                                       "' is a composite with no part that touches another "
                                       "body; " +
                                       what);
}

// Whether a joint joins the two bodies to each other.
bool joined(const Scenario& scenario, const std::string& a, const std::string& b) {
  return std::any_of(scenario.joints.begin(), scenario.joints.end(), [&](const JointSpec& j) {
    return (j.body_a == a && j.body_b == b) || (j.body_a == b && j.body_b == a);
  });
}

// Whether the body is welded to ground (a fixed obstacle: a bin's wall, a step).
bool welded_to_ground(const Scenario& scenario, const std::string& body) {
  return std::any_of(scenario.joints.begin(), scenario.joints.end(), [&](const JointSpec& j) {
    return j.type == JointType::Fixed && (j.body_a == kGroundName || j.body_b == kGroundName) &&
           (j.body_a == body || j.body_b == body);
  });
}

// Whether the body, or one of a composite's parts, has a shape that touches another body's.
bool can_touch_a_body(const BodySpec& body) {
  if (body.parts.empty()) return touches_a_body(body.shape.kind);
  return std::any_of(body.parts.begin(), body.parts.end(),
                     [](const PartSpec& part) { return touches_a_body(part.shape.kind); });
}

// `bodies: [a, b]`: two different bodies (not ground: a fixed surface is a plane's contact); or
// a group, `bodies: [a, b, c, ...]`: every pair of it, in the list's order (a-b, a-c, ..., b-c,
// ...), but those a joint joins to each other unless `joined: true`. Each pair into `pairs`
// (its bodies and parts).
void read_touching_bodies(const Reader& reader, const MapReader& map, const Scenario& scenario,
                          std::vector<ContactSpec>& pairs) {
  if (const auto f = map.find("plane")) {
    reader.fail_at_key(*f,
                       "a contact between two bodies has no plane (a body on a plane is "
                       "`type: plane` with `body:`)");
  }
  if (const auto f = map.find("body")) {
    reader.fail_at_key(*f, "a contact between two bodies names both in `bodies: [a, b]`");
  }
  if (const auto f = map.find("part")) {
    reader.fail_at_key(*f,
                       "a contact between two bodies touches at every part of each that can "
                       "(no `part:` to name: each pair of parts is a contact, NAME_PART)");
  }
  const Field list = map.require("bodies", "[a, b]: the two bodies that touch (or all)");
  std::vector<std::string> bodies;
  std::vector<std::vector<TouchingShape>> shapes;
  // `all`: every body with a shape that touches another body's, in `bodies:` order, but two
  // obstacles welded to ground (which never move).
  const bool all = list.node.IsScalar() && list.node.Scalar() == "all";
  if (all) {
    for (const BodySpec& body : scenario.bodies) {
      if (!can_touch_a_body(body)) continue;
      shapes.push_back(read_touching_shapes(reader, list, body));
      bodies.push_back(body.name);
    }
    if (bodies.size() < 2) {
      reader.fail_at_value(list, fmt::format("`all` finds {} bod{} whose shape touches another "
                                             "body's; a contact between bodies needs two",
                                             bodies.size(), bodies.size() == 1 ? "y" : "ies"));
    }
  } else {
    const std::vector<Field> names = reader.items(list, "of two bodies, [a, b], a group, or all");
    if (names.size() < 2) {
      reader.fail_at_value(
          list, fmt::format("a contact between bodies names two, [a, b] (or a group of more, "
                            "every pair of which may touch, or all); got {}",
                            names.size()));
    }
    for (const Field& name : names) {
      const std::string body = read_body_or_ground(reader, name, scenario.bodies, false);
      if (std::find(bodies.begin(), bodies.end(), body) != bodies.end()) {
        reader.fail_at_value(name,
                             "body '" + body + "' named twice: a contact is between two bodies");
      }
      shapes.push_back(
          read_touching_shapes(reader, name, scenario.bodies[*reader.body_position(body)]));
      bodies.push_back(body);
    }
  }
  const bool group = all || bodies.size() > 2;
  bool with_joined = true;
  if (const auto f = map.find("joined")) {
    if (!group) {
      reader.fail_at_key(*f,
                         "`joined:` is for a group of more than two bodies (a pair named on "
                         "its own touches whatever joins it)");
    }
    const std::string text = reader.text(*f);
    if (text != "true" && text != "false") {
      reader.fail_at_value(*f, "joined is true (pairs a joint joins touch too) or false");
    }
    with_joined = text == "true";
  } else {
    with_joined = !group;
  }
  for (std::size_t a = 0; a < bodies.size(); ++a) {
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      if (!with_joined && joined(scenario, bodies[a], bodies[b])) continue;
      if (all && welded_to_ground(scenario, bodies[a]) && welded_to_ground(scenario, bodies[b])) {
        continue;
      }
      // Each of a's touching parts against each of b's, but two that do not touch each other
      // (neither a sphere, nor both capsules).
      bool any = false;
      for (const TouchingShape& shape_a : shapes[a]) {
        for (const TouchingShape& shape_b : shapes[b]) {
          if (!touch_each_other(shape_a, shape_b)) continue;
          any = true;
          // The sphere is the contact's body (its columns are the sphere's): another shape named
          // first goes second. Two capsules keep the list's order.
          const bool swap = !shape_a.sphere() && shape_b.sphere();
          const TouchingShape& first = swap ? shape_b : shape_a;
          const TouchingShape& second = swap ? shape_a : shape_b;
          ContactSpec pair;
          // A group's pair is NAME_a_b, in the list's order, and a composite's part adds its name
          // where it has several that touch (NAME_head, NAME_a_b_head); a pair of one shape each,
          // named on its own, is NAME.
          std::vector<std::string> suffix;
          if (group) suffix = {bodies[a], bodies[b]};
          for (const TouchingShape* shape : {&shape_a, &shape_b}) {
            if (!shape->suffix.empty()) suffix.push_back(shape->suffix);
          }
          for (const std::string& piece : suffix) {
            pair.name += (pair.name.empty() ? "" : "_") + piece;
          }
          pair.body = bodies[swap ? b : a];
          pair.other_body = bodies[swap ? a : b];
          pair.part = first.part;
          pair.other_part = second.part;
          pair.screened = group;
          pairs.push_back(std::move(pair));
        }
      }
      if (!any && !group) {
        const ShapeKind kind_a = shapes[a].front().kind, kind_b = shapes[b].front().kind;
        reader.fail_at_value(
            list,
            kind_a == kind_b
                ? fmt::format("two {} do not touch each other yet: one of the two "
                              "bodies must be a sphere (or shell), or both capsules",
                              kind_a == ShapeKind::Box ? std::string("boxes")
                                                       : std::string(shape_name(kind_a)) + "s")
                : fmt::format("a {} and a {} do not touch each other yet: one of the two "
                              "bodies must be a sphere (or shell), or both capsules",
                              shape_name(kind_a), shape_name(kind_b)));
      }
      // A group's other shapes touch its spheres only (and its capsules each other).
    }
  }
  if (pairs.empty()) {
    reader.fail_at_value(
        list, with_joined ? std::string("no pair of this group can touch: two bodies touch "
                                        "where one of them is a sphere (or shell), or both are "
                                        "capsules")
                          : std::string("no pair of this group can touch: a joint joins every "
                                        "pair that has a sphere (or shell) or two capsules; add "
                                        "`joined: true` to let them touch"));
  }
}

// `friction:` and `restitution:`, as a plane's contact and a pair's take them. Between two
// bodies, `friction: inf` is friction without a limit: the two never slip on each other (a ball
// rolling off a dome, as the textbook states it).
void read_coefficients(const Reader& reader, const MapReader& map, ContactSpec& contact,
                       bool between_bodies) {
  const Field friction = map.require("friction", "Coulomb's mu >= 0; 0 is frictionless");
  if (friction.node.IsScalar() && friction.node.Scalar() == "inf") {
    if (!between_bodies) {
      reader.fail_at_value(friction,
                           "friction: inf (no slip, ever) is for contacts between two bodies; a "
                           "plane's contact takes a number >= 0");
    }
    contact.friction = std::numeric_limits<double>::infinity();
  } else {
    contact.friction = reader.number(friction);
  }
  if (!(contact.friction >= 0.0)) {
    reader.fail_at_value(
        friction, fmt::format("friction must be >= 0; got {}", format_number(contact.friction)));
  }
  if (const auto f = map.find("restitution")) {
    contact.restitution = reader.number(*f);
    if (!(contact.restitution >= 0.0 && contact.restitution <= 1.0)) {
      reader.fail_at_value(*f, fmt::format("restitution must be in [0, 1]; got {}",
                                           format_number(contact.restitution)));
    }
  }
}

// One contact, or a group's pairs, or a composite's parts on a plane: each of several named by
// the suffix its name takes (NAME_SUFFIX), one alone by none.
std::vector<ContactSpec> read_contact(const Reader& reader, const MapReader& map,
                                      const Scenario& scenario) {
  ContactSpec contact;
  const Field type = map.require("type", "plane, or bodies");
  if (reader.text(type) == "bodies") {
    std::vector<ContactSpec> pairs;
    read_touching_bodies(reader, map, scenario, pairs);
    for (ContactSpec& pair : pairs) read_coefficients(reader, map, pair, true);
    return pairs;
  }
  if (const auto f = map.find("joined")) {
    reader.fail_at_key(*f, "`joined:` is for a group of bodies that touch each other");
  }
  if (reader.text(type) != "plane") {
    reader.fail_at_value(type, "unknown contact type '" + reader.text(type) +
                                   "'; the types are plane (a fixed plane: ground, a ramp) and "
                                   "bodies (two bodies' surfaces)");
  }
  if (const auto f = map.find("bodies")) {
    reader.fail_at_key(*f,
                       "a contact with a plane names its one body in `body:` (two bodies "
                       "that touch each other are `type: bodies`)");
  }
  const Field body_field = map.require("body", "the body that touches the plane");
  contact.body = read_body_or_ground(reader, body_field, scenario.bodies, false);
  const BodySpec& body = scenario.bodies[*reader.body_position(contact.body)];
  std::vector<int> parts;
  if (!body.parts.empty()) {
    parts = read_touching_parts(reader, map, body_field, body);
  } else if (!touches_a_plane(body.shape.kind)) {
    reader.fail_at_value(body_field, "body '" + contact.body + "' is a " +
                                         std::string(shape_name(body.shape.kind)) +
                                         "; contact with a plane is for " + kTouchingShapes +
                                         ", or a composite's part of one of these shapes");
  } else if (const auto f = map.find("part")) {
    reader.fail_at_value(*f, "body '" + contact.body +
                                 "' is one shape, not a composite: it has "
                                 "no parts to name");
  }

  const Field plane = map.require("plane", "{point: [x, y, z], normal: [x, y, z]}");
  const MapReader plane_map(reader, plane, "a plane {point: [x, y, z], normal: [x, y, z]}");
  plane_map.allow_only({"point", "normal"}, "a plane");
  contact.plane_point_W =
      reader.point_or_vector(plane_map.require("point", "a point of the plane, m"));
  const Field normal = plane_map.require("normal", "out of the plane, towards the body");
  const std::optional<Vec3> n = unit_direction(reader.point_or_vector(normal));
  if (!n) reader.fail_at_value(normal, "the normal must not be zero");
  contact.plane_normal_W = *n;

  read_coefficients(reader, map, contact, false);
  if (parts.empty()) return {contact};
  std::vector<ContactSpec> each_part;
  for (const int part : parts) {
    each_part.push_back(contact);
    each_part.back().part = part;
    if (parts.size() > 1) each_part.back().name = part_suffix(body, part);
  }
  return each_part;
}

}  // namespace

std::unordered_map<std::string, std::size_t> inboard_joints(
    const Scenario& scenario, const std::vector<ContactSpec>& contacts) {
  BodyGroups groups;
  std::unordered_map<std::string, std::vector<std::size_t>> joints_at;
  for (std::size_t j = 0; j < scenario.joints.size(); ++j) {
    const JointSpec& joint = scenario.joints[j];
    if (joint.closes_loop) continue;  // a constraint on the tree, moving no body of its own
    groups.join(joint.body_a, joint.body_b);
    joints_at[joint.body_a].push_back(j);
    joints_at[joint.body_b].push_back(j);
  }
  // Each group's root: ground for the bodies joined to it, else the group's first body that
  // touches a plane, else its first body.
  std::unordered_set<std::string> touching;
  for (const ContactSpec& contact : contacts) touching.insert(contact.body);
  const std::string ground_group = groups.root(kGroundName);
  std::unordered_map<std::string, std::string> group_root = {{ground_group, kGroundName}};
  for (int pass = 0; pass < 2; ++pass) {
    for (const BodySpec& body : scenario.bodies) {
      if (pass == 0 && touching.count(body.name) == 0) continue;
      group_root.emplace(groups.root(body.name), body.name);
    }
  }
  // Out from each root through the joints: each body reached is held by the joint it is reached
  // through (the joints form a tree, so there is one).
  std::unordered_map<std::string, std::size_t> inboard;
  std::vector<char> used(scenario.joints.size(), 0);
  std::deque<std::string> frontier;
  for (const auto& [group, root] : group_root) {
    frontier.push_back(root);
    while (!frontier.empty()) {
      const std::string body = frontier.front();
      frontier.pop_front();
      const auto at = joints_at.find(body);
      if (at == joints_at.end()) continue;
      for (const std::size_t j : at->second) {
        if (used[j] != 0) continue;
        used[j] = 1;
        const JointSpec& joint = scenario.joints[j];
        const std::string& other = joint.body_a == body ? joint.body_b : joint.body_a;
        inboard.emplace(other, j);
        frontier.push_back(other);
      }
    }
  }
  return inboard;
}

std::vector<ContactSpec> read_contacts(const Reader& reader, const Field& field,
                                       const Scenario& scenario) {
  std::vector<ContactSpec> contacts;
  ColumnHeads heads(scenario);
  const std::vector<Field> items =
      reader.items(field, "of contacts, each {type: plane, ...} or {type: bodies, ...}");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const MapReader map(reader, items[i],
                        "a contact {type: plane, body:, plane: {point:, normal:}, friction:} or "
                        "{type: bodies, bodies: [a, b], friction:}");
    map.allow_only(
        {"type", "name", "body", "bodies", "joined", "part", "plane", "friction", "restitution"},
        "a contact");
    std::string name = "contact" + std::to_string(i + 1);
    const SourceLocation where = reader.location(items[i].key_mark);
    const auto name_field = map.find("name");
    const Field& named_at = name_field ? *name_field : items[i];
    if (name_field) {
      name = reader.text(*name_field);
      check_name(reader, *name_field, name, "contact");
    }
    // A group of bodies (more than two named) makes a contact of each pair, named by the group and
    // its bodies (touch_ball1_ball2), even where the joints leave one pair of it; a composite on a
    // plane, one of each part that touches where it has several (floor_head, floor_handle). Any
    // other contact's name is claimed before the rest of it is read.
    const auto listed = map.find("bodies");
    const bool all = listed && listed->node.IsScalar() && listed->node.Scalar() == "all";
    const bool group = all || (listed && listed->node.IsSequence() && listed->node.size() > 2);
    if (!group) heads.claim(reader, named_at, name, "contact", where);
    for (ContactSpec& contact : read_contact(reader, map, scenario)) {
      const bool one_of_several = !contact.name.empty();  // read_contact's suffix
      contact.name = one_of_several ? name + "_" + contact.name : name;
      if (all) contact.pool = name;
      contact.where = where;
      if (one_of_several) {
        check_name(reader, named_at, contact.name, "contact");
        heads.claim(reader, named_at, contact.name, "contact", where);
      }
      contacts.push_back(std::move(contact));
    }
  }
  return contacts;
}

}  // namespace tumble::scenario_reading
