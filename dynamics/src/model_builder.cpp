// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_builder.hpp"

#include <algorithm>
#include <array>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/gravity.hpp"
#include "clearjoint/dynamics/point_load.hpp"
#include "clearjoint/dynamics/spring_damper.hpp"

namespace clearjoint::dynamics {

namespace {

BodyIndex find_body(const ModelDescription& model, std::string_view name, const std::string& field) {
  if (name == kGroundName) return kGround;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].properties.name == name) return static_cast<BodyIndex>(b);
  }
  throw ModelError(field + " = \"" + std::string(name) +
                   "\": no body of that name (use \"ground\" for the world frame)");
}

void require_unique_names(const ModelDescription& model) {
  for (size_t a = 0; a < model.bodies.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (model.bodies[a].properties.name == model.bodies[b].properties.name) {
        throw ModelError("bodies[" + std::to_string(a) + "].name = \"" +
                         model.bodies[a].properties.name + "\": used by bodies[" +
                         std::to_string(b) + "] already");
      }
    }
  }
}

/// The model file's keys of a clearance joint's parts: the pin-in-hole's hole and pin, else the
/// paper's bearing and journal.
std::string bearing_key(const ClearanceRevoluteDescription& d) {
  return d.parameters.pin_in_hole ? ".hole" : ".bearing";
}
std::string journal_key(const ClearanceRevoluteDescription& d) {
  return d.parameters.pin_in_hole ? ".pin" : ".journal";
}

struct ForceBuilder {
  const ModelDescription& model;
  std::string field;
  std::unique_ptr<ForceElement> operator()(const PointLoadDescription& d) const {
    return std::make_unique<PointLoad>(d.name, find_body(model, d.body, field + ".body"), d.point_B,
                                       d.force_W, d.moment_W);
  }
  std::unique_ptr<ForceElement> operator()(const ClearanceRevoluteDescription& d) const {
    const ClearanceJointPart bearing{find_body(model, d.bearing.body, field + bearing_key(d) + ".body"),
                                     d.bearing.point_B, d.bearing.axis_B};
    const ClearanceJointPart journal{find_body(model, d.journal.body, field + journal_key(d) + ".body"),
                                     d.journal.point_B, d.journal.axis_B};
    return std::make_unique<ClearanceRevoluteJoint>(d.name, bearing, journal, d.parameters);
  }
  std::unique_ptr<ForceElement> operator()(const SpringDamperDescription& d) const {
    return std::make_unique<SpringDamper>(d.name, find_body(model, d.body_i, field + ".body_i"),
                                          d.point_i_B, find_body(model, d.body_j, field + ".body_j"),
                                          d.point_j_B, d.parameters);
  }
};

}  // namespace

int held_component_index(std::string_view name, bool velocity, std::string_view field) {
  static constexpr std::array<std::string_view, 6> kPositions{"x", "y", "z", "rx", "ry", "rz"};
  static constexpr std::array<std::string_view, 6> kVelocities{"vx", "vy", "vz", "wx", "wy", "wz"};
  const auto& names = velocity ? kVelocities : kPositions;
  for (int k = 0; k < 6; ++k) {
    if (names[k] == name) return k;
  }
  throw ModelError(std::string(field) + " = \"" + std::string(name) + "\": must be one of " +
                   (velocity ? "vx, vy, vz, wx, wy, wz" : "x, y, z, rx, ry, rz"));
}

namespace {

/// A model's mechanism, checked: its bodies (properties, initial guesses), its joints' equations
/// at those poses, and the coordinates held while the initial conditions are made consistent.
struct Mechanism {
  std::vector<BodyProperties> properties;
  std::vector<BodyState> states;
  std::vector<JointEquations> joints;
  std::vector<HeldCoordinate> held_positions;
  std::vector<HeldVelocity> held_velocities;
};

/// The bodies and joints of `model` into `mechanism`.
void add_bodies_and_joints(const ModelDescription& model, Mechanism& mechanism) {
  if (model.bodies.empty()) throw ModelError("bodies: the model has no bodies");
  require_unique_names(model);
  const int n = static_cast<int>(model.bodies.size());
  SystemKinematics initial(n);
  for (BodyIndex b = 0; b < n; ++b) {
    const std::string field = "bodies[" + std::to_string(b) + "]";
    validate(model.bodies[b].properties, field);
    validate(model.bodies[b].initial, field);
    mechanism.properties.push_back(model.bodies[b].properties);
    mechanism.states.push_back(model.bodies[b].initial);
    mechanism.states.back().euler_parameters.normalize();
    initial.set(b, mechanism.states.back());
  }
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const JointDescription& j = model.joints[k];
    const std::string field = "joints[" + std::to_string(k) + "]";
    validate(j, field);
    for (size_t other = 0; other < k; ++other) {
      if (model.joints[other].name == j.name) {
        throw ModelError(field + ".name = \"" + j.name + "\": used by joints[" + std::to_string(other) + "] already");
      }
    }
    mechanism.joints.push_back(JointEquations::build(j, find_body(model, j.body_i, field + ".body_i"),
                                                     find_body(model, j.body_j, field + ".body_j"), initial));
  }
}

std::string_view force_name(const ForceDescription& force) {
  return std::visit([](const auto& d) -> std::string_view { return d.name; }, force);
}

/// forces[k]'s name must differ from the earlier forces' names.
void require_unique_force_name(const ModelDescription& model, size_t k) {
  const std::string_view name = force_name(model.forces[k]);
  for (size_t other = 0; other < k; ++other) {
    if (force_name(model.forces[other]) == name) {
      throw ModelError("forces[" + std::to_string(k) + "].name = \"" + std::string(name) +
                       "\": used by forces[" + std::to_string(other) + "] already");
    }
  }
}

/// The bodies a force description names, each with its field ("forces[2].body_i").
struct ForceBodies {
  const ModelDescription& model;
  std::string field;
  void operator()(const PointLoadDescription& d) const { find_body(model, d.body, field + ".body"); }
  void operator()(const ClearanceRevoluteDescription& d) const {
    find_body(model, d.bearing.body, field + bearing_key(d) + ".body");
    find_body(model, d.journal.body, field + journal_key(d) + ".body");
  }
  void operator()(const SpringDamperDescription& d) const {
    find_body(model, d.body_i, field + ".body_i");
    find_body(model, d.body_j, field + ".body_j");
  }
};

/// The held coordinates of `model` into `mechanism`, and the output bodies checked.
void add_held_coordinates(const ModelDescription& model, Mechanism& mechanism) {
  for (size_t k = 0; k < model.held_positions.size(); ++k) {
    const auto& h = model.held_positions[k];
    const std::string field = "initial_conditions.hold_positions[" + std::to_string(k) + "]";
    const BodyIndex body = find_body(model, h.body, field + ".body");
    if (body == kGround) throw ModelError(field + ".body = \"ground\": the ground is always held");
    mechanism.held_positions.push_back({body, held_component_index(h.component, false, field + ".components")});
    for (size_t other = 0; other < k; ++other) {
      if (model.held_positions[other].body == h.body && model.held_positions[other].component == h.component) {
        throw ModelError(field + " = (\"" + h.body + "\", \"" + h.component +
                         "\"): held already by hold_positions[" + std::to_string(other) + "]");
      }
    }
  }
  for (size_t k = 0; k < model.held_velocities.size(); ++k) {
    const auto& h = model.held_velocities[k];
    const std::string field = "initial_conditions.hold_velocities[" + std::to_string(k) + "]";
    const BodyIndex body = find_body(model, h.body, field + ".body");
    if (body == kGround) throw ModelError(field + ".body = \"ground\": the ground is always at rest");
    mechanism.held_velocities.push_back({body, held_component_index(h.component, true, field + ".component"), h.value});
    // Two values for one component cannot both hold; the later one must not win silently.
    for (size_t other = 0; other < k; ++other) {
      if (model.held_velocities[other].body == h.body && model.held_velocities[other].component == h.component) {
        throw ModelError(field + " = (\"" + h.body + "\", \"" + h.component + "\", " +
                         format_number(h.value) + "): the same component is held by hold_velocities[" +
                         std::to_string(other) + "] = " + format_number(model.held_velocities[other].value));
      }
    }
  }
  for (size_t k = 0; k < model.output_bodies.size(); ++k) {
    const BodyIndex body = find_body(model, model.output_bodies[k], "output.bodies[" + std::to_string(k) + "]");
    if (body == kGround) throw ModelError("output.bodies[" + std::to_string(k) + "] = \"ground\": the ground does not move");
    for (size_t other = 0; other < k; ++other) {
      if (model.output_bodies[other] == model.output_bodies[k]) {
        throw ModelError("output.bodies[" + std::to_string(k) + "] = \"" + model.output_bodies[k] +
                         "\": listed already as output.bodies[" + std::to_string(other) + "]");
      }
    }
  }
}

/// Every name in output.force_elements must be a force element's: gravity's (when the model has
/// gravity, build_model adds it under that name) or a described force's.
void require_known_output_forces(const ModelDescription& model) {
  if (model.output_all_force_elements) return;
  const bool has_gravity = model.gravity_W.squaredNorm() > 0.0;
  for (size_t k = 0; k < model.output_force_elements.size(); ++k) {
    const std::string& name = model.output_force_elements[k];
    const bool known = (has_gravity && name == kGravityName) ||
                       std::any_of(model.forces.begin(), model.forces.end(),
                                   [&](const auto& f) { return force_name(f) == name; });
    if (!known) {
      throw ModelError("output.force_elements[" + std::to_string(k) + "] = \"" + name +
                       "\": no force element of that name");
    }
  }
}

}  // namespace

BuiltModel build_model(const ModelDescription& model) {
  Mechanism mechanism;
  add_bodies_and_joints(model, mechanism);

  std::vector<std::unique_ptr<ForceElement>> forces;
  if (model.gravity_W.squaredNorm() > 0.0) {
    std::vector<double> masses;
    for (const BodyProperties& p : mechanism.properties) masses.push_back(p.mass);
    forces.push_back(std::make_unique<Gravity>(std::move(masses), model.gravity_W));
  }
  for (size_t k = 0; k < model.forces.size(); ++k) {
    forces.push_back(std::visit(ForceBuilder{model, "forces[" + std::to_string(k) + "]"}, model.forces[k]));
    require_unique_force_name(model, k);
  }

  add_held_coordinates(model, mechanism);
  require_known_output_forces(model);

  BuiltModel built;
  built.system = std::make_unique<MultibodySystem>(std::move(mechanism.properties), std::move(mechanism.joints),
                                                   std::move(forces), model.baumgarte);
  built.initial_conditions = make_consistent(*built.system, model.solver.start_time, mechanism.states,
                                             mechanism.held_positions, mechanism.held_velocities);
  built.initial_states = mechanism.states;
  built.initial_state = built.system->pack(mechanism.states);
  return built;
}

ConsistentStart consistent_start(const ModelDescription& model) {
  Mechanism mechanism;
  add_bodies_and_joints(model, mechanism);
  require_finite("gravity", model.gravity_W);  // as Gravity's constructor checks it
  for (size_t k = 0; k < model.forces.size(); ++k) {
    std::visit(ForceBodies{model, "forces[" + std::to_string(k) + "]"}, model.forces[k]);
    require_unique_force_name(model, k);
  }
  add_held_coordinates(model, mechanism);
  require_known_output_forces(model);

  // make_consistent reads the bodies and the constraints alone: a system without force elements
  // gives build_model's states, bit for bit.
  MultibodySystem mechanism_only(std::move(mechanism.properties), std::move(mechanism.joints), {},
                                 model.baumgarte);
  ConsistentStart start;
  start.initial_conditions = make_consistent(mechanism_only, model.solver.start_time, mechanism.states,
                                             mechanism.held_positions, mechanism.held_velocities);
  start.initial_states = std::move(mechanism.states);
  return start;
}

}  // namespace clearjoint::dynamics
