// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/json_input/json_reader.hpp"
#include "clearjoint/json_input/read_detection_options.hpp"

namespace clearjoint::dynamics {

namespace {

using json::Json;

/// Relative slack of the inertia triangle inequality: a flat plate's Izz = Ixx + Iyy written
/// with 6 significant digits can fall short by a few parts in 1e7.
constexpr double kInertiaTriangleSlack = 1e-6;

/// Largest grid size per direction of a lubricated joint: 4096 x 4096 is 1.7e7 unknowns, far past
/// any accuracy need (docs/lubrication.md) and a bound that keeps the count an int.
constexpr double kMaxGridCells = 4096.0;

/// `value` in the shortest form that reads back to it (1e-12, not format_number's
/// 9.9999999999999998e-13): the limits and values of the range messages below read as written.
std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string shortest(const Vector3& v) {
  return "[" + shortest(v[0]) + ", " + shortest(v[1]) + ", " + shortest(v[2]) + "]";
}

/// A value of the model file with its path ("bodies[1].mass"), read with the shared JSON reader
/// (clearjoint/json_input/json_reader.hpp); what it adds is the model's: "comment" and "notes" allowed in
/// every object, names, and Eigen vectors.
class Node {
 public:
  explicit Node(json::JsonField field) : field_(std::move(field)) {}

  const std::string& path() const { return field_.path(); }
  std::string field(std::string_view key) const { return field_.member_path(key); }

  void require_object(std::initializer_list<std::string_view> allowed) const {
    field_.require_object(allowed, {"comment", "notes"});
  }
  void require_object(const std::vector<std::string_view>& allowed) const {
    field_.require_object(allowed, {"comment", "notes"});
  }

  bool has(std::string_view key) const { return field_.has(key); }
  json::JsonField member(std::string_view key) const { return field_.member(key); }
  Node child(std::string_view key) const { return Node(field_.member(key)); }

  double number(std::string_view key) const { return field_.member(key).number(); }
  double number(std::string_view key, double fallback) const {
    return has(key) ? number(key) : fallback;
  }

  std::string text(std::string_view key) const { return field_.member(key).text(); }
  std::string text(std::string_view key, std::string fallback) const {
    return has(key) ? text(key) : fallback;
  }
  /// A name (of a body, joint or force element): non-empty, at most kMaxNameBytes, since names
  /// become file names (body_<name>.csv) and CSV column headers.
  std::string name(std::string_view key) const {
    const json::JsonField entry = field_.member(key);
    std::string value = entry.text();
    if (value.empty()) entry.refuse("must not be empty");
    if (value.size() > kMaxNameBytes) {
      entry.refuse("longer than " + std::to_string(kMaxNameBytes) + " bytes, the limit for a name");
    }
    return value;
  }

  template <int N>
  Eigen::Matrix<double, N, 1> vector(std::string_view key) const {
    const auto numbers = field_.member(key).numbers<N>();
    return Eigen::Map<const Eigen::Matrix<double, N, 1>>(numbers.data());
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vector(std::string_view key,
                                     const Eigen::Matrix<double, N, 1>& fallback) const {
    return has(key) ? vector<N>(key) : fallback;
  }

  std::vector<Node> array(std::string_view key) const {
    std::vector<Node> items;
    for (json::JsonField& entry : field_.member(key).items()) items.emplace_back(std::move(entry));
    return items;
  }
  std::vector<Node> array_or_empty(std::string_view key) const {
    return has(key) ? array(key) : std::vector<Node>{};
  }
  /// An array of strings, e.g. body names; `what` says what each must be ("a body name").
  std::vector<std::string> names(std::string_view key, std::string_view what) const {
    std::vector<std::string> result;
    for (const json::JsonField& entry : field_.member(key).items()) {
      if (!entry.json().is_string()) entry.refuse("must be " + std::string(what));
      result.push_back(entry.text());
    }
    return result;
  }

 private:
  json::JsonField field_;
};

/// Principal moments of a real body obey I1 + I2 >= I3 (each is a sum of two of the three
/// second moments of the mass distribution). A model that breaks it has a typo or swapped
/// values; the equations would run, with motions no body can have.
void check_inertia(const Vector3& inertia, const std::string& field) {
  for (int k = 0; k < 3; ++k) {
    const double others = inertia[(k + 1) % 3] + inertia[(k + 2) % 3];
    if (others < inertia[k] * (1.0 - kInertiaTriangleSlack)) {
      throw ModelError(field + " = " + shortest(inertia) + ": inertia[" + std::to_string(k) +
                       "] is larger than the sum of the other two, which no body has (principal "
                       "moments obey the triangle inequality)");
    }
  }
}

/// Throws unless `value` (already known positive) is within [smallest, largest].
void check_range(const std::string& field, double value, double smallest, double largest,
                 const char* unit) {
  if (value < smallest || value > largest) {
    throw ModelError(field + " = " + shortest(value) + ": outside [" + shortest(smallest) + ", " +
                     shortest(largest) + "] " + unit +
                     ", the range accepted (check the units)");
  }
}

BodyDescription parse_body(const Node& n) {
  n.require_object({"name", "mass", "inertia", "position", "euler_parameters", "velocity",
                    "angular_velocity"});
  BodyDescription b;
  b.properties.name = n.name("name");
  b.properties.mass = n.number("mass");
  b.properties.principal_inertia = n.vector<3>("inertia");
  b.initial.position_W = n.vector<3>("position");
  b.initial.euler_parameters = n.vector<4>("euler_parameters", Vector4(1.0, 0.0, 0.0, 0.0));
  b.initial.velocity_W = n.vector<3>("velocity", Vector3::Zero());
  b.initial.angular_velocity_B = n.vector<3>("angular_velocity", Vector3::Zero());
  validate(b.properties, n.path());
  validate(b.initial, n.path());
  check_range(n.field("mass"), b.properties.mass, kSmallestMass, kLargestMass, "kg");
  for (int k = 0; k < 3; ++k) {
    check_range(n.field("inertia") + "[" + std::to_string(k) + "]", b.properties.principal_inertia[k],
                kSmallestInertia, kLargestInertia, "kg m^2");
  }
  check_inertia(b.properties.principal_inertia, n.field("inertia"));
  return b;
}

JointDescription parse_joint(const Node& n) {
  n.require_object({"name", "type", "body_i", "body_j", "point_i", "point_j", "axis_i", "axis_j",
                    "angle_rate", "angle_acceleration"});
  JointDescription j;
  j.name = n.name("name");
  j.type = joint_type_from_string(n.text("type"), n.field("type"));
  j.body_i = n.text("body_i");
  j.body_j = n.text("body_j");
  j.point_i_B = n.vector<3>("point_i", Vector3::Zero());
  j.point_j_B = n.vector<3>("point_j", Vector3::Zero());
  j.axis_i_B = n.vector<3>("axis_i", Vector3::UnitZ());
  j.axis_j_B = n.vector<3>("axis_j", j.axis_i_B);
  j.angle.rate = n.number("angle_rate", 0.0);
  j.angle.acceleration = n.number("angle_acceleration", 0.0);
  validate(j, n.path());
  return j;
}

/// One cylinder of a clearance joint: {"body", "point", "axis", "radius", "length"}.
ClearancePartDescription parse_clearance_part(const Node& n, double& radius, double& length) {
  n.require_object({"body", "point", "axis", "radius", "length"});
  radius = n.number("radius");
  length = n.number("length");
  return {n.text("body"), n.vector<3>("point", Vector3::Zero()), n.vector<3>("axis")};
}

/// The pin of a pin-in-hole joint: {"body", "point", "axis", "radius", "stops"}, each stop
/// {"position", "outer_radius"}, spelled as the command line's detect line (docs/command-line.md).
/// The stops' positions and sizes are the kernel's to check (validate(PinInHoleDimensions), by
/// the joint); only their number is checked here, as the description holds at most two.
ClearancePartDescription parse_pin(const Node& n, geometry::PinInHoleDimensions& d) {
  n.require_object({"body", "point", "axis", "radius", "stops"});
  d.pin_radius = n.number("radius");
  const std::vector<Node> stops = n.array_or_empty("stops");
  if (stops.size() > static_cast<std::size_t>(geometry::kMaxAxialStops)) {
    n.member("stops").refuse("at most " + std::to_string(geometry::kMaxAxialStops) +
                             " stops (one on each side of the hole; [] for a free sliding pin)");
  }
  d.stop_count = static_cast<int>(stops.size());
  for (std::size_t k = 0; k < stops.size(); ++k) {
    stops[k].require_object({"position", "outer_radius"});
    d.stops[k] = {stops[k].number("position"), stops[k].number("outer_radius")};
  }
  return {n.text("body"), n.vector<3>("point", Vector3::Zero()), n.vector<3>("axis")};
}

/// A clearance joint's oil film: {"viscosity", "cavitation", "method", "grid", "allow_large_grid", "groove_direction",
/// "supply_pressure", "film_thickness_limit", "transition_width"} (joint_lubrication.hpp).
JointLubrication parse_lubrication(const Node& n) {
  n.require_object({"viscosity", "cavitation", "method", "grid", "allow_large_grid", "groove_direction",
                    "supply_pressure", "film_thickness_limit", "transition_width"});
  JointLubrication l;
  l.viscosity = n.number("viscosity");
  l.cavitation = cavitation_model_from_string(
      n.text("cavitation", std::string(lubrication::to_string(l.cavitation))), n.field("cavitation"));
  l.method = film_method_from_string(n.text("method", std::string(lubrication::to_string(l.method))),
                                     n.field("method"));
  if (n.has("grid")) {
    const Eigen::Vector2d grid = n.vector<2>("grid");
    for (int k = 0; k < 2; ++k) {
      if (!(grid[k] >= 1.0 && grid[k] <= kMaxGridCells && grid[k] == std::floor(grid[k]))) {
        throw ModelError(n.field("grid") + "[" + std::to_string(k) + "] = " + shortest(grid[k]) +
                         ": must be a whole number of cells in [1, " + shortest(kMaxGridCells) + "]");
      }
    }
    l.circumferential_cells = static_cast<int>(grid[0]);
    l.axial_cells = static_cast<int>(grid[1]);
  }
  if (n.has("allow_large_grid")) l.allow_large_grid = n.member("allow_large_grid").boolean();
  if (n.has("groove_direction")) l.groove_direction_B = n.vector<3>("groove_direction");
  l.supply_pressure = n.number("supply_pressure", 0.0);
  l.film_thickness_limit = n.number("film_thickness_limit");
  l.transition_width = n.number("transition_width", l.film_thickness_limit);
  // Checked once, by the joint built from this description in parse_clearance_revolute under
  // the file's path (forces[k].lubrication.viscosity = ...: must be in [...]), after the
  // dimensions whose radial clearance bounds film_thickness_limit and transition_width.
  return l;
}

ClearanceRevoluteDescription parse_clearance_revolute(const Node& n) {
  ClearanceRevoluteDescription d;
  const std::string geometry_kind = n.text("geometry", "journal_bearing");
  if (geometry_kind == "pin_in_hole") {
    // The hole is the bearing (body i), the pin the journal (body j).
    n.require_object({"type", "name", "geometry", "hole", "pin", "normal_force", "friction", "detection",
                      "lubrication"});
    d.name = n.name("name");
    geometry::PinInHoleDimensions& dims = d.parameters.pin_in_hole.emplace();
    d.bearing = parse_clearance_part(n.child("hole"), dims.hole_radius, dims.hole_length);
    d.journal = parse_pin(n.child("pin"), dims);
  } else if (geometry_kind == "journal_bearing") {
    n.require_object({"type", "name", "geometry", "bearing", "journal", "normal_force", "friction",
                      "detection", "lubrication"});
    d.name = n.name("name");
    geometry::JointDimensions& dims = d.parameters.dimensions;
    d.bearing = parse_clearance_part(n.child("bearing"), dims.bearing_radius, dims.bearing_length);
    d.journal = parse_clearance_part(n.child("journal"), dims.journal_radius, dims.journal_length);
  } else {
    n.member("geometry").refuse("must be \"journal_bearing\" (the paper's joint, the default) or \"pin_in_hole\"");
  }

  const Node normal = n.child("normal_force");
  normal.require_object({"model", "stiffness", "exponent", "restitution", "minimum_impact_speed"});
  NormalForceParameters& p = d.parameters.normal;
  p.model = normal_force_model_from_string(normal.text("model"), normal.field("model"));
  p.stiffness = normal.number("stiffness");
  p.exponent = normal.number("exponent", p.exponent);
  p.restitution = p.model == NormalForceModel::hertz ? normal.number("restitution", 1.0)
                                                     : normal.number("restitution");
  p.minimum_impact_speed = normal.number("minimum_impact_speed", p.minimum_impact_speed);

  // No "friction" object: frictionless.
  FrictionParameters& f = d.parameters.friction;
  f.coefficient = 0.0;
  if (n.has("friction")) {
    const Node friction = n.child("friction");
    friction.require_object({"coefficient", "velocity_coefficient"});
    f.coefficient = friction.number("coefficient");
    f.velocity_coefficient = friction.number("velocity_coefficient", f.velocity_coefficient);
  }
  if (n.has("detection")) {
    // Every option of the detection, by the keys of the command line's "options".
    json::read_detection_options(n.member("detection"), d.parameters.detection, {"comment", "notes"});
  }
  if (n.has("lubrication")) d.parameters.lubrication = parse_lubrication(n.child("lubrication"));
  // Validate here so that messages name the file's fields (forces[k].journal.radius, ...); body
  // names are resolved later by the model builder.
  ClearanceRevoluteJoint(n.path(), {0, d.bearing.point_B, d.bearing.axis_B},
                         {1, d.journal.point_B, d.journal.axis_B}, d.parameters);
  return d;
}

ForceDescription parse_force(const Node& n) {
  const std::string type = n.text("type");
  if (type == "point_load") {
    n.require_object({"type", "name", "body", "point", "force", "moment"});
    return PointLoadDescription{n.name("name"), n.text("body"), n.vector<3>("point", Vector3::Zero()),
                                n.vector<3>("force", Vector3::Zero()),
                                n.vector<3>("moment", Vector3::Zero())};
  }
  if (type == "spring_damper") {
    n.require_object({"type", "name", "body_i", "body_j", "point_i", "point_j", "stiffness",
                      "damping", "free_length"});
    return SpringDamperDescription{
        n.name("name"), n.text("body_i"), n.text("body_j"), n.vector<3>("point_i", Vector3::Zero()),
        n.vector<3>("point_j", Vector3::Zero()),
        {n.number("stiffness"), n.number("damping", 0.0), n.number("free_length")}};
  }
  if (type == "clearance_revolute") return parse_clearance_revolute(n);
  throw ModelError(n.field("type") + " = \"" + json::excerpt(type) +
                   "\": unknown force type (known: point_load, spring_damper, clearance_revolute; "
                   "gravity is the top-level \"gravity\" vector)");
}

void parse_initial_conditions(const Node& n, ModelDescription& model) {
  n.require_object({"hold_positions", "hold_velocities"});
  for (const Node& h : n.array_or_empty("hold_positions")) {
    h.require_object({"body", "components"});
    const std::string body = h.text("body");
    const json::JsonField components = h.member("components");
    if (!components.json().is_array()) {
      components.refuse("must be an array such as [\"x\", \"y\", \"z\", \"rx\", \"ry\", \"rz\"]");
    }
    for (const json::JsonField& component : components.items()) {
      model.held_positions.push_back({body, component.text()});
    }
  }
  for (const Node& h : n.array_or_empty("hold_velocities")) {
    h.require_object({"body", "component", "value"});
    model.held_velocities.push_back({h.text("body"), h.text("component"), h.number("value")});
  }
}

/// The Moreau-Jean scheme's keys of "solver" (solver_method.hpp); a compliant model may not set
/// them, since nothing would read them.
void parse_moreau_jean_settings(const Node& n, ModelDescription& model) {
  MoreauJeanSettings& m = model.moreau_jean;
  for (std::string_view key : {"step", "theta", "contact_tolerance", "contact_max_iterations",
                               "stop_on_unconverged"}) {
    if (n.has(key) && model.solver_method != SolverMethod::moreau_jean) {
      throw ModelError(n.field(key) + ": only read with \"method\": \"moreau_jean\"");
    }
  }
  m.step = n.number("step", m.step);
  m.theta = n.number("theta", m.theta);
  m.contact_tolerance = n.number("contact_tolerance", m.contact_tolerance);
  const double iterations = n.number("contact_max_iterations", m.contact_max_iterations);
  if (!(iterations >= 1.0 && iterations <= 1e9 && iterations == std::floor(iterations))) {
    throw ModelError(n.field("contact_max_iterations") + " = " + format_number(iterations) +
                     ": must be a whole number in [1, 1e9]");
  }
  m.contact_max_iterations = static_cast<int>(iterations);
  if (n.has("stop_on_unconverged")) m.stop_on_unconverged = n.member("stop_on_unconverged").boolean();
  validate(m, n.path());
}

void parse_solver(const Node& n, ModelDescription& model) {
  n.require_object({"start_time", "end_time", "report_step", "relative_tolerance",
                    "absolute_tolerance", "initial_step", "minimum_step", "max_steps",
                    "baumgarte_alpha", "baumgarte_beta", "method", "step", "theta",
                    "contact_tolerance", "contact_max_iterations", "stop_on_unconverged"});
  if (n.has("method")) model.solver_method = solver_method_from_string(n.text("method"), n.field("method"));
  parse_moreau_jean_settings(n, model);
  IntegratorSettings& s = model.solver;
  s.start_time = n.number("start_time", s.start_time);
  s.end_time = n.number("end_time", s.end_time);
  s.report_step = n.number("report_step", s.report_step);
  s.relative_tolerance = n.number("relative_tolerance", s.relative_tolerance);
  s.absolute_tolerance = n.number("absolute_tolerance", s.absolute_tolerance);
  s.initial_step = n.number("initial_step", s.initial_step);
  s.minimum_step = n.number("minimum_step", s.minimum_step);
  // A count: read whole, within 2^53 where a double holds every whole number and a long converts
  // it exactly; its range is validate()'s (solver.max_steps).
  const double max_steps = n.number("max_steps", static_cast<double>(s.max_steps));
  if (!(max_steps == std::floor(max_steps) && std::fabs(max_steps) <= 0x1p53)) {
    throw ModelError(n.field("max_steps"), " = " + format_number(max_steps) +
                                               ": must be a whole number of steps (at most 2^53 in size)");
  }
  s.max_steps = static_cast<long>(max_steps);
  model.baumgarte.alpha = n.number("baumgarte_alpha", model.baumgarte.alpha);
  model.baumgarte.beta = n.number("baumgarte_beta", model.baumgarte.beta);
  validate(s);
}

}  // namespace

ModelDescription parse_model(std::string_view json_text, std::string_view source) {
  try {
    const Json json = json::parse_input(json_text, kMaxModelFileBytes, "a model file");
    const Node root(json::JsonField(json, "", "the model"));
    root.require_object({"name", "gravity", "bodies", "joints", "forces", "initial_conditions",
                         "solver", "output"});
    ModelDescription model;
    model.name = root.text("name", std::string(source));
    model.notes = root.text("notes", "");
    model.gravity_W = root.vector<3>("gravity", Vector3::Zero());
    if (!(model.gravity_W.norm() <= kLargestGravity)) {
      throw ModelError("gravity = " + shortest(model.gravity_W) + ": magnitude above " +
                       shortest(kLargestGravity) + " m/s^2, the largest accepted (check the units)");
    }
    for (const Node& b : root.array("bodies")) model.bodies.push_back(parse_body(b));
    for (const Node& j : root.array_or_empty("joints")) model.joints.push_back(parse_joint(j));
    for (const Node& f : root.array_or_empty("forces")) model.forces.push_back(parse_force(f));
    if (root.has("initial_conditions")) parse_initial_conditions(root.child("initial_conditions"), model);
    if (root.has("solver")) parse_solver(root.child("solver"), model);
    bool all_bodies = true;
    if (root.has("output")) {
      const Node output = root.child("output");
      output.require_object({"bodies", "force_elements", "decimation"});
      if (output.has("decimation")) {
        const double decimation = output.number("decimation", 1.0);
        if (!(decimation >= 1.0 && decimation <= kMaxDecimation && decimation == std::floor(decimation))) {
          throw ModelError(output.field("decimation") + " = " + format_number(decimation) +
                           ": must be a whole number in [1, " + format_number(kMaxDecimation) + "]");
        }
        model.output_decimation = static_cast<long>(decimation);
      }
      if (output.has("bodies")) {
        model.output_bodies = output.names("bodies", "a body name");
        all_bodies = false;
      }
      if (output.has("force_elements")) {
        model.output_force_elements = output.names("force_elements", "a force element name");
        model.output_all_force_elements = false;
      }
    }
    if (all_bodies) {
      for (const BodyDescription& b : model.bodies) model.output_bodies.push_back(b.properties.name);
    }
    return model;
  } catch (const ValidationError& e) {
    // The reader's, the description's and the joint's checks alike: named with the file, the
    // field's path kept (ValidationError::field_path()).
    throw ModelError(e, source);
  }
}

std::string read_model_text(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw ModelError(path.string() + ": is a directory, not a model file");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw ModelError(path.string() + ": cannot open the model file");
  // Read at most one byte past the limit: a huge file (or /dev/zero) is refused, not slurped;
  // parse_model names the limit.
  std::string text(kMaxModelFileBytes + 1, '\0');
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (file.bad()) throw ModelError(path.string() + ": cannot read the model file");
  text.resize(static_cast<size_t>(file.gcount()));
  return text;
}

ModelDescription read_model_file(const std::filesystem::path& path) {
  return parse_model(read_model_text(path), path.string());
}

}  // namespace clearjoint::dynamics
