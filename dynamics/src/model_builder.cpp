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

struct ForceBuilder {
  const ModelDescription& model;
  std::string field;
  std::unique_ptr<ForceElement> operator()(const PointLoadDescription& d) const {
    return std::make_unique<PointLoad>(d.name, find_body(model, d.body, field + ".body"), d.point_B,
                                       d.force_W, d.moment_W);
  }
  std::unique_ptr<ForceElement> operator()(const ClearanceRevoluteDescription& d) const {
    const ClearanceJointPart bearing{find_body(model, d.bearing.body, field + ".bearing.body"),
                                     d.bearing.point_B, d.bearing.axis_B};
    const ClearanceJointPart journal{find_body(model, d.journal.body, field + ".journal.body"),
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

BuiltModel build_model(const ModelDescription& model) {
  if (model.bodies.empty()) throw ModelError("bodies: the model has no bodies");
  require_unique_names(model);
  const int n = static_cast<int>(model.bodies.size());

  std::vector<BodyProperties> properties;
  std::vector<BodyState> states;
  SystemKinematics initial(n);
  for (BodyIndex b = 0; b < n; ++b) {
    const std::string field = "bodies[" + std::to_string(b) + "]";
    validate(model.bodies[b].properties, field);
    validate(model.bodies[b].initial, field);
    properties.push_back(model.bodies[b].properties);
    states.push_back(model.bodies[b].initial);
    states.back().euler_parameters.normalize();
    initial.set(b, states.back());
  }

  std::vector<JointEquations> joints;
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const JointDescription& j = model.joints[k];
    const std::string field = "joints[" + std::to_string(k) + "]";
    validate(j, field);
    for (size_t other = 0; other < k; ++other) {
      if (model.joints[other].name == j.name) {
        throw ModelError(field + ".name = \"" + j.name + "\": used by joints[" + std::to_string(other) + "] already");
      }
    }
    joints.push_back(JointEquations::build(j, find_body(model, j.body_i, field + ".body_i"),
                                           find_body(model, j.body_j, field + ".body_j"), initial));
  }

  std::vector<std::unique_ptr<ForceElement>> forces;
  if (model.gravity_W.squaredNorm() > 0.0) {
    std::vector<double> masses;
    for (const BodyProperties& p : properties) masses.push_back(p.mass);
    forces.push_back(std::make_unique<Gravity>(std::move(masses), model.gravity_W));
  }
  const size_t first_described_force = forces.size();  // after gravity, which has no name of the model's
  for (size_t k = 0; k < model.forces.size(); ++k) {
    forces.push_back(std::visit(ForceBuilder{model, "forces[" + std::to_string(k) + "]"}, model.forces[k]));
    for (size_t other = 0; other < k; ++other) {
      if (forces[first_described_force + other]->name() == forces.back()->name()) {
        throw ModelError("forces[" + std::to_string(k) + "].name = \"" + std::string(forces.back()->name()) +
                         "\": used by forces[" + std::to_string(other) + "] already");
      }
    }
  }

  std::vector<HeldCoordinate> held_positions;
  for (size_t k = 0; k < model.held_positions.size(); ++k) {
    const auto& h = model.held_positions[k];
    const std::string field = "initial_conditions.hold_positions[" + std::to_string(k) + "]";
    const BodyIndex body = find_body(model, h.body, field + ".body");
    if (body == kGround) throw ModelError(field + ".body = \"ground\": the ground is always held");
    held_positions.push_back({body, held_component_index(h.component, false, field + ".components")});
    for (size_t other = 0; other < k; ++other) {
      if (model.held_positions[other].body == h.body && model.held_positions[other].component == h.component) {
        throw ModelError(field + " = (\"" + h.body + "\", \"" + h.component +
                         "\"): held already by hold_positions[" + std::to_string(other) + "]");
      }
    }
  }
  std::vector<HeldVelocity> held_velocities;
  for (size_t k = 0; k < model.held_velocities.size(); ++k) {
    const auto& h = model.held_velocities[k];
    const std::string field = "initial_conditions.hold_velocities[" + std::to_string(k) + "]";
    const BodyIndex body = find_body(model, h.body, field + ".body");
    if (body == kGround) throw ModelError(field + ".body = \"ground\": the ground is always at rest");
    held_velocities.push_back({body, held_component_index(h.component, true, field + ".component"), h.value});
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

  if (!model.output_all_force_elements) {
    for (size_t k = 0; k < model.output_force_elements.size(); ++k) {
      const std::string& name = model.output_force_elements[k];
      const bool known = std::any_of(forces.begin(), forces.end(),
                                     [&](const auto& f) { return f->name() == name; });
      if (!known) {
        throw ModelError("output.force_elements[" + std::to_string(k) + "] = \"" + name +
                         "\": no force element of that name");
      }
    }
  }

  BuiltModel built;
  built.system = std::make_unique<MultibodySystem>(std::move(properties), std::move(joints),
                                                   std::move(forces), model.baumgarte);
  built.initial_conditions = make_consistent(*built.system, model.solver.start_time, states,
                                             held_positions, held_velocities);
  built.initial_states = states;
  built.initial_state = built.system->pack(states);
  return built;
}

}  // namespace clearjoint::dynamics
