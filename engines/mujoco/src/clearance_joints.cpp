// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/mujoco/clearance_joints.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "two_body_clearance_joint.hpp"

namespace clearjoint::mujoco {

namespace {

constexpr std::string_view kPrefix = "clearance:";

/// The installed adapters, one per model; mjcb_passive is a single global hook.
std::vector<ClearanceJoints*>& installed() {
  static std::vector<ClearanceJoints*> adapters;
  return adapters;
}
std::vector<const mjModel*>& installed_models() {
  static std::vector<const mjModel*> models;
  return models;
}

void passive_callback(const mjModel* m, mjData* d) {
  for (size_t k = 0; k < installed().size(); ++k) {
    if (installed_models()[k] == m) installed()[k]->add_passive_forces(d);
  }
}

std::string text_of(const mjModel* m, int id) {
  // text_size counts the terminating zero.
  return std::string(m->text_data + m->text_adr[id], std::max(0, m->text_size[id] - 1));
}

/// The values of the numeric element `name`, which must hold `count` of them; empty when the
/// model has no such element.
std::vector<double> numeric(const mjModel* m, const std::string& name, int count) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, name.c_str());
  if (id < 0) return {};
  if (m->numeric_size[id] != count) {
    throw ModelError("<numeric name=\"" + name + "\">: holds " + std::to_string(m->numeric_size[id]) +
                     " values, needs " + std::to_string(count));
  }
  const mjtNum* data = m->numeric_data + m->numeric_adr[id];
  return std::vector<double>(data, data + count);
}

/// Every value of the numeric element `name`; empty when the model has no such element.
std::vector<double> all_numeric(const mjModel* m, const std::string& name) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, name.c_str());
  if (id < 0) return {};
  const mjtNum* data = m->numeric_data + m->numeric_adr[id];
  return std::vector<double>(data, data + m->numeric_size[id]);
}

/// The fields a joint's declaration may have, by element type (clearance_joints.hpp).
constexpr std::array<std::string_view, 5> kNumericFields = {"dimensions", "normal_force", "friction",
                                                            "parallel_angle_tolerance", "pin_in_hole"};
constexpr std::array<std::string_view, 2> kTextFields = {"normal_force_model", "geometry"};
/// The values of geometry (a model file's "geometry", dynamics/src/model_file.cpp).
constexpr std::string_view kJournalBearing = "journal_bearing";
constexpr std::string_view kPinInHole = "pin_in_hole";

/// The geometry the joint `key` ("clearance:<name>") declares: kJournalBearing without a
/// <text name="<key>:geometry"> element.
std::string geometry_of(const mjModel* m, const std::string& key) {
  const int id = mj_name2id(m, mjOBJ_TEXT, (key + ":geometry").c_str());
  return id < 0 ? std::string(kJournalBearing) : text_of(m, id);
}

/// The oil film's fields in a model file (dynamics/src/model_file.cpp, parse_lubrication), and
/// the object's own name: a declaration of a film, which the adapter does not run.
constexpr std::array<std::string_view, 10> kFilmFields = {
    "lubrication",      "viscosity",      "cavitation", "method", "grid", "allow_large_grid", "groove_direction",
    "supply_pressure", "film_thickness_limit", "transition_width"};

template <size_t N>
std::string joined(const std::array<std::string_view, N>& names) {
  std::string list;
  for (std::string_view name : names) (list += list.empty() ? "" : ", ") += name;
  return list;
}

template <size_t N>
bool is_one_of(const std::string& field, const std::array<std::string_view, N>& names) {
  return std::find(names.begin(), names.end(), field) != names.end();
}

/// Refuses every <text> or <numeric> element named "clearance:..." that no declaration reads (a
/// misspelt field would otherwise leave its joint at the default values without a word).
void refuse_unknown_keys(const mjModel* m) {
  std::vector<std::string> joints;
  for (int t = 0; t < m->ntext; ++t) {
    const char* name = mj_id2name(m, mjOBJ_TEXT, t);
    const std::string key = name == nullptr ? "" : name;
    if (key.starts_with(kPrefix) && key.find(':', kPrefix.size()) == std::string::npos) {
      joints.push_back(key.substr(kPrefix.size()));
    }
  }
  std::string joint_list;
  for (const std::string& joint : joints) (joint_list += joint_list.empty() ? "\"" : ", \"") += joint + "\"";
  const auto check = [&](mjtObj type, int id) {
    const char* name = mj_id2name(m, type, id);
    const std::string key = name == nullptr ? "" : name;
    if (!key.starts_with(kPrefix)) return;
    const std::string element = std::string(type == mjOBJ_TEXT ? "<text" : "<numeric") + " name=\"" + key + "\">";
    const size_t colon = key.find(':', kPrefix.size());
    if (colon == std::string::npos) {
      if (type == mjOBJ_TEXT) return;  // a declaration
      throw ModelError(element + ": a clearance joint is declared by a <text> element naming its two sites");
    }
    const std::string joint = key.substr(kPrefix.size(), colon - kPrefix.size());
    const std::string field = key.substr(colon + 1);
    if (std::find(joints.begin(), joints.end(), joint) == joints.end()) {
      throw ModelError(element + ": no clearance joint \"" + joint + "\" is declared (<text name=\"clearance:" +
                       joint + "\">); the declared ones: " + (joint_list.empty() ? "none" : joint_list));
    }
    if (is_one_of(field, kFilmFields) && geometry_of(m, std::string(kPrefix) + joint) == kPinInHole) {
      // As the joint itself refuses a film on a pin (dynamics::ClearanceRevoluteJoint).
      throw ModelError(element + ": an oil film is not supported with geometry \"pin_in_hole\" (the oil film is "
                       "the journal-bearing's; remove the element or use the paper's joint)");
    }
    if (is_one_of(field, kFilmFields)) {
      throw ModelError(element + ": lubricated clearance joints are not supported by the MuJoCo adapter; use "
                       "clearjoint simulate (--engine clearjoint or --engine simbody) with a model file");
    }
    const bool known = type == mjOBJ_TEXT ? is_one_of(field, kTextFields) : is_one_of(field, kNumericFields);
    const bool other_type = type == mjOBJ_TEXT ? is_one_of(field, kNumericFields) : is_one_of(field, kTextFields);
    if (other_type) {
      throw ModelError(element + ": \"" + field + "\" must be a <" + (type == mjOBJ_TEXT ? "numeric" : "text") +
                       "> element");
    }
    if (!known) {
      throw ModelError(element + ": unknown field \"" + field + "\"; a clearance joint's <numeric> fields are " +
                       joined(kNumericFields) + ", its <text> fields " + joined(kTextFields));
    }
  };
  for (int t = 0; t < m->ntext; ++t) check(mjOBJ_TEXT, t);
  for (int n = 0; n < m->nnumeric; ++n) check(mjOBJ_NUMERIC, n);
}

int site(const mjModel* m, const std::string& name, const std::string& declaration) {
  const int id = mj_name2id(m, mjOBJ_SITE, name.c_str());
  if (id < 0) throw ModelError(declaration + ": no site named \"" + name + "\" in the model");
  return id;
}

/// P and a of a site in its body's frame: the site's position and its frame's z axis.
dynamics::ClearanceJointPart part_at(const mjModel* m, int site_id) {
  const mjtNum z[3] = {0.0, 0.0, 1.0};
  mjtNum axis[3];
  mju_rotVecQuat(axis, z, m->site_quat + 4 * site_id);
  const mjtNum* p = m->site_pos + 3 * site_id;
  return {dynamics::kGround, dynamics::Vector3(p[0], p[1], p[2]),
          dynamics::Vector3(axis[0], axis[1], axis[2])};
}

/// The dimensions of a pin-in-hole joint `name` from <numeric name="<key>:pin_in_hole">, in the
/// model file's order: hole.radius hole.length pin.radius, then position outer_radius for each of
/// 0, 1 or 2 stops. Checked by the kernel's validate(PinInHoleDimensions) under the model file's
/// names ("<name>.pin.stops[1].position"), its error sourced to the element.
geometry::PinInHoleDimensions read_pin_in_hole(const mjModel* m, const std::string& key, const std::string& name,
                                               const std::string& declaration) {
  const std::string field_key = key + ":pin_in_hole";
  const std::string element = "<numeric name=\"" + field_key + "\">";
  constexpr size_t kSizeValues = 3;  // hole.radius hole.length pin.radius
  constexpr size_t kStopValues = 2;  // position outer_radius
  if (mj_name2id(m, mjOBJ_NUMERIC, (key + ":dimensions").c_str()) >= 0) {
    throw ModelError("<numeric name=\"" + key + ":dimensions\">: not used with geometry \"pin_in_hole\", whose "
                     "sizes are " + element);
  }
  if (mj_name2id(m, mjOBJ_NUMERIC, field_key.c_str()) < 0) {
    throw ModelError(declaration + ": geometry \"pin_in_hole\" needs <numeric name=\"" + field_key +
                     "\" data=\"Rh L Rp [position outer_radius]...\"/> (metres)");
  }
  const std::vector<double> values = all_numeric(m, field_key);
  const size_t n = values.size();
  if (n < kSizeValues || (n - kSizeValues) % kStopValues != 0 ||
      (n - kSizeValues) / kStopValues > static_cast<size_t>(geometry::kMaxAxialStops)) {
    throw ModelError(element + ": holds " + std::to_string(n) +
                     " values, needs 3, 5 or 7: hole.radius hole.length pin.radius, then pin.stops[k].position "
                     "pin.stops[k].outer_radius for each of 0, 1 or 2 stops");
  }
  const int stops = static_cast<int>((n - kSizeValues) / kStopValues);
  geometry::PinInHoleDimensions d;
  d.hole_radius = values[0];
  d.hole_length = values[1];
  d.pin_radius = values[2];
  d.stop_count = stops;
  for (size_t k = 0; k < static_cast<size_t>(stops); ++k) {
    d.stops[k] = {values[kSizeValues + kStopValues * k], values[kSizeValues + kStopValues * k + 1]};
  }
  try {
    // The one check of these dimensions, the kernel's; the joint makes it again under the same
    // names, but here the element that holds the values can be named.
    geometry::validate(d, name, geometry::kPinInHolePartNames);
  } catch (const geometry::InvalidInput& e) {
    throw ModelError(e, element);
  }
  return d;
}

engines::RigidMotion motion_of(const mjModel* m, const mjData* d, int body) {
  engines::RigidMotion motion;
  const mjtNum* p = d->xpos + 3 * body;
  motion.origin_W = {p[0], p[1], p[2]};
  // xmat is row-major.
  motion.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * body);
  if (body != 0) {
    mjtNum v[6];  // [angular; linear] at the body frame's origin, world axes
    mj_objectVelocity(m, d, mjOBJ_XBODY, body, v, 0);
    motion.angular_velocity_W = {v[0], v[1], v[2]};
    motion.velocity_W = {v[3], v[4], v[5]};
  }
  return motion;
}

}  // namespace

struct ClearanceJoints::Joint {
  int bearing_body = 0;
  int journal_body = 0;
  mutable engines::TwoBodyClearanceJoint joint;
  std::array<double, dynamics::kContactSlotCount> memory{};

  void load(const mjModel* m, const mjData* d) const {
    joint.set_motions(d->time, motion_of(m, d, bearing_body), motion_of(m, d, journal_body));
  }
};

ClearanceJoints::ClearanceJoints(const mjModel* model) : model_(model) {
  refuse_unknown_keys(model);
  for (int t = 0; t < model->ntext; ++t) {
    const char* text_name = mj_id2name(model, mjOBJ_TEXT, t);
    if (text_name == nullptr) continue;
    const std::string key(text_name);
    if (key.rfind(kPrefix, 0) != 0 || key.find(':', kPrefix.size()) != std::string::npos) continue;
    const std::string name = key.substr(kPrefix.size());
    const std::string declaration = "<text name=\"" + key + "\">";
    std::istringstream sites(text_of(model, t));
    std::string bearing_site, journal_site, extra;
    if (!(sites >> bearing_site >> journal_site) || (sites >> extra)) {
      throw ModelError(declaration + ": data must name two sites, the bearing's then the journal's");
    }
    const int bearing = site(model, bearing_site, declaration);
    const int journal = site(model, journal_site, declaration);

    dynamics::ClearanceJointParameters parameters;
    const std::string geometry_kind = geometry_of(model, key);
    if (geometry_kind == kPinInHole) {
      parameters.pin_in_hole = read_pin_in_hole(model, key, name, declaration);
    } else if (geometry_kind == kJournalBearing) {
      if (mj_name2id(model, mjOBJ_NUMERIC, (key + ":pin_in_hole").c_str()) >= 0) {
        throw ModelError("<numeric name=\"" + key + ":pin_in_hole\">: needs <text name=\"" + key +
                         ":geometry\" data=\"pin_in_hole\"/>; the paper's joint (geometry \"journal_bearing\", "
                         "the default) has its sizes in <numeric name=\"" + key + ":dimensions\">");
      }
      const std::string dimensions_key = key + ":dimensions";
      const std::vector<double> dimensions = numeric(model, dimensions_key, 4);
      if (dimensions.empty()) {
        throw ModelError(declaration + ": needs <numeric name=\"" + dimensions_key +
                         "\" data=\"Ri Li Rj Lj\"/> (metres)");
      }
      parameters.dimensions = {dimensions[0], dimensions[1], dimensions[2], dimensions[3]};
    } else {
      throw ModelError("<text name=\"" + key + ":geometry\">: \"" + geometry_kind +
                       "\": must be \"journal_bearing\" (the paper's joint, the default) or \"pin_in_hole\"");
    }
    const int law = mj_name2id(model, mjOBJ_TEXT, (key + ":normal_force_model").c_str());
    try {
      if (law >= 0) {
        parameters.normal.model =
            dynamics::normal_force_model_from_string(text_of(model, law), key + ":normal_force_model");
      }
      if (const auto v = numeric(model, key + ":normal_force", 4); !v.empty()) {
        parameters.normal.stiffness = v[0];
        parameters.normal.exponent = v[1];
        parameters.normal.restitution = v[2];
        parameters.normal.minimum_impact_speed = v[3];
      }
      if (const auto v = numeric(model, key + ":friction", 2); !v.empty()) {
        parameters.friction = {v[0], v[1]};
      }
      if (const auto v = numeric(model, key + ":parallel_angle_tolerance", 1); !v.empty()) {
        parameters.detection.parallel_angle_tolerance = v[0];
      }
      const int bearing_body = model->site_bodyid[bearing];
      const int journal_body = model->site_bodyid[journal];
      if (bearing_body == journal_body) {
        throw ModelError(declaration + ": sites \"" + bearing_site + "\" and \"" + journal_site +
                         "\" are on one body; the bearing and the journal must be on two");
      }
      joints_.push_back(std::unique_ptr<Joint>(new Joint{
          bearing_body, journal_body,
          engines::TwoBodyClearanceJoint(name, part_at(model, bearing), part_at(model, journal), parameters),
          {}}));
    } catch (const ModelError&) {
      throw;  // the adapter's own, already naming the element
    } catch (const dynamics::ModelError& e) {
      // The joint's own checks name "<name>.<field>"; say where the joint was declared, keeping
      // the field's path for a program that matches it.
      throw ModelError(e, declaration);
    }
  }
}

ClearanceJoints::~ClearanceJoints() {
  if (!installed_) return;
  for (size_t k = 0; k < installed().size(); ++k) {
    if (installed()[k] == this) {
      installed().erase(installed().begin() + static_cast<long>(k));
      installed_models().erase(installed_models().begin() + static_cast<long>(k));
      break;
    }
  }
  if (installed().empty()) mjcb_passive = nullptr;
}

void ClearanceJoints::install() {
  if (installed_) return;
  installed().push_back(this);
  installed_models().push_back(model_);
  installed_ = true;
  mjcb_passive = passive_callback;
}

void ClearanceJoints::add_passive_forces(mjData* data) const {
  for (const auto& j : joints_) {
    j->load(model_, data);
    // Force and moment about each body's frame origin (xpos): one mj_applyFT per body.
    const engines::BodyWrenches w = j->joint.wrenches(j->memory);
    if (j->journal_body != 0) {
      mj_applyFT(model_, data, w.force_on_journal_W.data(), w.moment_on_journal_W.data(),
                 data->xpos + 3 * j->journal_body, j->journal_body, data->qfrc_passive);
    }
    if (j->bearing_body != 0) {
      mj_applyFT(model_, data, w.force_on_bearing_W.data(), w.moment_on_bearing_W.data(),
                 data->xpos + 3 * j->bearing_body, j->bearing_body, data->qfrc_passive);
    }
  }
}

bool ClearanceJoints::after_step(mjData* data) {
  bool changed = false;
  for (const auto& j : joints_) {
    j->load(model_, data);
    changed = j->joint.update_impact_memory(j->memory) || changed;
  }
  return changed;
}

int ClearanceJoints::count() const { return static_cast<int>(joints_.size()); }

const dynamics::ClearanceRevoluteJoint& ClearanceJoints::joint(int k) const { return joints_[k]->joint.joint(); }

std::span<const double> ClearanceJoints::impact_memory(int k) const { return joints_[k]->memory; }

void ClearanceJoints::record_outputs(int k, const mjData* data, std::span<double> values) const {
  joints_[k]->load(model_, data);
  joints_[k]->joint.record_outputs(joints_[k]->memory, values);
}

double ClearanceJoints::potential_energy(const mjData* data) const {
  double energy = 0.0;
  for (const auto& j : joints_) {
    j->load(model_, data);
    energy += j->joint.potential_energy();
  }
  return energy;
}

}  // namespace clearjoint::mujoco
