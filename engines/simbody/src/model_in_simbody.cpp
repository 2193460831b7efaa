// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/simbody/model_in_simbody.hpp"

#include <variant>

#include "clearjoint/dynamics/spring_damper.hpp"

namespace clearjoint::simbody {

namespace {

using dynamics::JointDescription;
using dynamics::JointType;
using dynamics::Vector3;

/// The ground's index in the model's body numbering (dynamics::kGround).
constexpr int kGround = dynamics::kGround;

SimTK::Vec3 to_simtk(const Vector3& v) { return {v[0], v[1], v[2]}; }

std::string joint_field(size_t k, const JointDescription& joint) {
  return "joints[" + std::to_string(k) + "] \"" + joint.name + "\" (" +
         std::string(dynamics::to_string(joint.type)) + ")";
}

/// The features the route does not build, named before anything is built.
void refuse_unsupported(const dynamics::ModelDescription& model) {
  for (size_t k = 0; k < model.joints.size(); ++k) {
    if (model.joints[k].type == JointType::angle_driver) {
      throw UnsupportedFeature(joint_field(k, model.joints[k]) +
                               ": the Simbody route has no angle drivers (a prescribed motion); "
                               "run this model with --engine clearjoint");
    }
  }
  for (size_t k = 0; k < model.forces.size(); ++k) {
    if (const auto* load = std::get_if<dynamics::PointLoadDescription>(&model.forces[k])) {
      throw UnsupportedFeature("forces[" + std::to_string(k) + "] \"" + load->name +
                               "\" (point_load): the Simbody route has no point loads; run this "
                               "model with --engine clearjoint");
    }
  }
}

/// Pose and world velocities of a body at the start (the consistent initial state), or of the
/// ground.
struct InitialMotion {
  SimTK::Transform X_GB;
  SimTK::Vec3 w_G{0.0};  ///< angular velocity
  SimTK::Vec3 v_G{0.0};  ///< velocity of the body origin (the mass centre)
};

InitialMotion initial_motion(const dynamics::BodyState& s) {
  const SimTK::Quaternion q(SimTK::Vec4(s.euler_parameters[0], s.euler_parameters[1],
                                        s.euler_parameters[2], s.euler_parameters[3]));
  const SimTK::Rotation R_GB(q);
  return {SimTK::Transform(R_GB, to_simtk(s.position_W)), R_GB * to_simtk(s.angular_velocity_B),
          to_simtk(s.velocity_W)};
}

/// The parent-side frame F of a joint's mobilizer, in the parent's frame (see the header's table).
SimTK::Rotation mobilizer_axes(JointType type, const Vector3& parent_axis_P,
                               const Vector3& child_axis_P) {
  const SimTK::UnitVec3 axis(to_simtk(parent_axis_P));
  switch (type) {
    case JointType::revolute:
    case JointType::cylindrical: return SimTK::Rotation(axis, SimTK::ZAxis);
    case JointType::translational: return SimTK::Rotation(axis, SimTK::XAxis);
    case JointType::universal:
      // x: the parent's cross axis; y: the child's, as it lies at the start (perpendicular).
      return SimTK::Rotation(axis, SimTK::XAxis, to_simtk(child_axis_P), SimTK::YAxis);
    default: return SimTK::Rotation();  // spherical, fixed: the parent's axes
  }
}

}  // namespace

SimbodyModel::SimbodyModel(const dynamics::ModelDescription& model) {
  refuse_unsupported(model);
  // The model's checks and the consistent initial state both engines start from, without
  // clearjoint's force elements: this route builds its own (below), which check their constants.
  const dynamics::ConsistentStart start = dynamics::consistent_start(model);
  initial_conditions_ = start.initial_conditions;

  system_ = std::make_unique<SimTK::MultibodySystem>();
  matter_ = std::make_unique<SimTK::SimbodyMatterSubsystem>(*system_);
  forces_ = std::make_unique<SimTK::GeneralForceSubsystem>(*system_);
  if (model.gravity_W != Vector3::Zero()) {
    SimTK::Force::UniformGravity(*forces_, *matter_, to_simtk(model.gravity_W));
  }

  const int body_count = static_cast<int>(model.bodies.size());
  std::vector<InitialMotion> motion;
  for (const dynamics::BodyDescription& b : model.bodies) body_names_.push_back(b.properties.name);
  for (const dynamics::BodyState& s : start.initial_states) motion.push_back(initial_motion(s));
  auto index_of = [&](const std::string& name) {
    for (int b = 0; b < body_count; ++b) {
      if (body_names_[b] == name) return b;
    }
    return kGround;  // consistent_start has checked every name
  };
  auto motion_of = [&](int b) { return b == kGround ? InitialMotion{} : motion[b]; };
  bodies_.resize(body_count);
  std::vector<bool> in_tree(body_count, false);
  auto mobod = [&](int b) -> SimTK::MobilizedBody& {
    return b == kGround ? matter_->updGround() : bodies_[b];
  };
  auto is_in_tree = [&](int b) { return b == kGround || in_tree[b]; };
  auto rigid_body = [&](int b) {
    const dynamics::BodyProperties& p = model.bodies[b].properties;
    return SimTK::Body::Rigid(SimTK::MassProperties(
        p.mass, SimTK::Vec3(0.0),
        SimTK::Inertia(p.principal_inertia[0], p.principal_inertia[1], p.principal_inertia[2])));
  };

  // The spanning tree, joints other than spherical first (see the header).
  const size_t joint_count = model.joints.size();
  std::vector<bool> in_tree_joint(joint_count, false);
  joints_.resize(joint_count);
  // The mobilizers in the order made (parents first), with F's initial velocity for the fit.
  struct Made {
    SimTK::MobilizedBody body;
    SimTK::SpatialVec V_FM;
  };
  std::vector<Made> made;
  auto attach = [&](size_t k) {
    const JointDescription& joint = model.joints[k];
    const int i = index_of(joint.body_i);
    const int j = index_of(joint.body_j);
    const bool parent_is_i = is_in_tree(i);
    const int parent = parent_is_i ? i : j;
    const int child = parent_is_i ? j : i;
    const Vector3& parent_point = parent_is_i ? joint.point_i_B : joint.point_j_B;
    const Vector3& parent_axis = parent_is_i ? joint.axis_i_B : joint.axis_j_B;
    const Vector3& child_axis = parent_is_i ? joint.axis_j_B : joint.axis_i_B;
    const InitialMotion P = motion_of(parent);
    const InitialMotion B = motion_of(child);
    // The child's axis in the parent frame at the start, for the universal joint's F.
    const Vector3 child_axis_P = [&] {
      const SimTK::Vec3 a = ~P.X_GB.R() * (B.X_GB.R() * to_simtk(child_axis));
      return Vector3(a[0], a[1], a[2]);
    }();
    const SimTK::Rotation R_PF = mobilizer_axes(joint.type, parent_axis, child_axis_P);
    const SimTK::Transform X_PF(R_PF, to_simtk(parent_point));
    // M is F carried into the child at the start: every mobilizer starts at q = 0.
    const SimTK::Transform X_GF = P.X_GB * X_PF;
    const SimTK::Transform X_BM = ~B.X_GB * X_GF;
    SimTK::MobilizedBody& parent_body = mobod(parent);
    const SimTK::Body::Rigid body = rigid_body(child);
    SimTK::MobilizedBody m;
    switch (joint.type) {
      case JointType::revolute: m = SimTK::MobilizedBody::Pin(parent_body, X_PF, body, X_BM); break;
      case JointType::spherical: m = SimTK::MobilizedBody::Ball(parent_body, X_PF, body, X_BM); break;
      case JointType::universal: m = SimTK::MobilizedBody::Universal(parent_body, X_PF, body, X_BM); break;
      case JointType::cylindrical: m = SimTK::MobilizedBody::Cylinder(parent_body, X_PF, body, X_BM); break;
      case JointType::translational: m = SimTK::MobilizedBody::Slider(parent_body, X_PF, body, X_BM); break;
      case JointType::fixed: m = SimTK::MobilizedBody::Weld(parent_body, X_PF, body, X_BM); break;
      case JointType::angle_driver: break;  // refused above
    }
    bodies_[child] = m;
    in_tree[child] = true;
    in_tree_joint[k] = true;
    // V_FM in F: relative angular velocity, and the velocity of M's origin relative to F's
    // (they coincide at the start, so no transport term).
    const SimTK::Vec3 p_GFo = X_GF.p();
    const SimTK::Vec3 v_Fo = P.v_G + P.w_G % (p_GFo - P.X_GB.p());
    const SimTK::Vec3 v_Mo = B.v_G + B.w_G % (p_GFo - B.X_GB.p());
    made.push_back({m, SimTK::SpatialVec(~X_GF.R() * (B.w_G - P.w_G), ~X_GF.R() * (v_Mo - v_Fo))});

    JointInSimbody& r = joints_[k];
    r.name = joint.name;
    const bool report_i = j == kGround;
    r.reported_body = m;  // replaced below when the parent is the reported body
    r.reported_body_is_child = (report_i ? i : j) == child;
    if (!r.reported_body_is_child) r.reported_body = mobod(report_i ? i : j);
    r.point_on_reported_body = to_simtk(report_i ? joint.point_i_B : joint.point_j_B);
    r.mobilizer = m;
  };
  auto one_end_in_tree = [&](size_t k) {
    return is_in_tree(index_of(model.joints[k].body_i)) != is_in_tree(index_of(model.joints[k].body_j));
  };
  for (;;) {
    bool attached = false;
    for (int pass = 0; pass < 2 && !attached; ++pass) {
      const bool spherical_pass = pass == 1;
      for (size_t k = 0; k < joint_count && !attached; ++k) {
        if (in_tree_joint[k] || !one_end_in_tree(k)) continue;
        if ((model.joints[k].type == JointType::spherical) != spherical_pass) continue;
        attach(k);
        attached = true;
      }
    }
    if (attached) continue;
    // A body no joint reaches: free, with F at its initial pose so that it starts at q = 0.
    int free_body = -1;
    for (int b = 0; b < body_count && free_body < 0; ++b) {
      if (!in_tree[b]) free_body = b;
    }
    if (free_body < 0) break;
    const InitialMotion B = motion[free_body];
    SimTK::MobilizedBody::Free m(matter_->updGround(), B.X_GB, rigid_body(free_body), SimTK::Transform());
    bodies_[free_body] = m;
    in_tree[free_body] = true;
    made.push_back({m, SimTK::SpatialVec(~B.X_GB.R() * B.w_G, ~B.X_GB.R() * B.v_G)});
  }

  // Loops: closed by spherical joints only.
  for (size_t k = 0; k < joint_count; ++k) {
    if (in_tree_joint[k]) continue;
    const JointDescription& joint = model.joints[k];
    if (joint.type != JointType::spherical) {
      throw UnsupportedFeature(joint_field(k, joint) +
                               ": closes a kinematic loop, and the Simbody route closes loops only "
                               "with spherical joints (Constraint::Ball); run this model with "
                               "--engine clearjoint");
    }
    const int i = index_of(joint.body_i);
    const int j = index_of(joint.body_j);
    JointInSimbody& r = joints_[k];
    r.name = joint.name;
    r.closes_loop = true;
    r.loop = SimTK::Constraint::Ball(mobod(i), to_simtk(joint.point_i_B), mobod(j),
                                     to_simtk(joint.point_j_B));
    r.reported_body_is_child = j != kGround;  // body 2 of the constraint is reported
    r.reported_body = mobod(j == kGround ? i : j);
    r.point_on_reported_body = to_simtk(j == kGround ? joint.point_i_B : joint.point_j_B);
  }

  for (size_t k = 0; k < model.forces.size(); ++k) {
    if (const auto* c = std::get_if<dynamics::ClearanceRevoluteDescription>(&model.forces[k])) {
      clearance_joints_.push_back(std::make_unique<ClearanceRevoluteForce>(
          *system_, *forces_, c->name,
          ClearancePartInBody{mobod(index_of(c->bearing.body)), to_simtk(c->bearing.point_B),
                              to_simtk(c->bearing.axis_B)},
          ClearancePartInBody{mobod(index_of(c->journal.body)), to_simtk(c->journal.point_B),
                              to_simtk(c->journal.axis_B)},
          c->parameters));
    } else if (const auto* s = std::get_if<dynamics::SpringDamperDescription>(&model.forces[k])) {
      dynamics::validate_spring_damper(s->name, s->point_i_B, s->point_j_B, s->parameters);
      SimTK::MobilizedBody& bi = mobod(index_of(s->body_i));
      SimTK::MobilizedBody& bj = mobod(index_of(s->body_j));
      const SimTK::Vec3 pi = to_simtk(s->point_i_B);
      const SimTK::Vec3 pj = to_simtk(s->point_j_B);
      SimTK::Force::TwoPointLinearSpring(*forces_, bi, pi, bj, pj, s->parameters.stiffness,
                                         s->parameters.free_length);
      if (s->parameters.damping > 0.0) {
        SimTK::Force::TwoPointLinearDamper(*forces_, bi, pi, bj, pj, s->parameters.damping);
      }
    }
  }

  initial_state_ = system_->realizeTopology();
  initial_state_.setTime(model.solver.start_time);
  system_->realize(initial_state_, SimTK::Stage::Position);
  for (const Made& m : made) m.body.setUToFitVelocity(initial_state_, m.V_FM);
  system_->realize(initial_state_, SimTK::Stage::Velocity);
  for (const auto& clearance : clearance_joints_) clearance->initialize_impact_memory(initial_state_);
  system_->realize(initial_state_, SimTK::Stage::Velocity);
}

const SimTK::MobilizedBody& SimbodyModel::body(const std::string& name, const std::string& field) const {
  if (name == dynamics::kGroundName) return matter_->getGround();
  for (size_t b = 0; b < body_names_.size(); ++b) {
    if (body_names_[b] == name) return bodies_[b];
  }
  throw dynamics::ModelError(field + " = \"" + name + "\": no body of that name");
}

}  // namespace clearjoint::simbody
