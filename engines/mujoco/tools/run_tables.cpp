// SPDX-License-Identifier: BSD-3-Clause
#include "run_tables.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>
#include <stdexcept>

namespace clearjoint::mujoco_tool {

namespace {

/// `clearjoint simulate`'s body table columns (dynamics/src/simulation.cpp, body_header).
std::vector<std::string> body_header() {
  return {"time", "x", "y", "z", "e0", "e1", "e2", "e3", "vx", "vy", "vz", "wx", "wy", "wz",
          "ax", "ay", "az", "alphax", "alphay", "alphaz"};
}

std::string folded(std::string name) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

}  // namespace

RunTables::RunTables(mjModel* model, const mujoco::ClearanceJoints& clearance)
    : model_(model), clearance_(clearance) {
  std::vector<std::pair<std::string, std::string>> seen;  // folded file name, what it is for
  const auto add = [&](std::string name, std::vector<std::string> header, const std::string& what) {
    for (const auto& [other, other_what] : seen) {
      if (other == folded(name)) {
        throw std::runtime_error(what + ": its output file " + name + ".csv has the name of " + other_what +
                                 "'s (names are compared after characters other than letters, digits, - and _ "
                                 "become _, and without case); rename one of them");
      }
    }
    seen.emplace_back(folded(name), what);
    tables_.push_back({std::move(name), std::move(header)});
  };
  for (int b = 1; b < model->nbody; ++b) {
    const char* name = mj_id2name(model, mjOBJ_BODY, b);
    const std::string body = name != nullptr && *name != '\0' ? name : "body" + std::to_string(b);
    bodies_.push_back(b);
    add(dynamics::table_name("body_", body), body_header(), "<body name=\"" + body + "\">");
  }
  add("energy", {"time", "kinetic", "potential", "total"}, "the energy table");
  for (int k = 0; k < clearance.count(); ++k) {
    std::vector<std::string> header = clearance.joint(k).output_columns();
    header.insert(header.begin(), "time");
    add(dynamics::table_name("force_", clearance.joint(k).name()), std::move(header),
        "clearance joint \"" + std::string(clearance.joint(k).name()) + "\"");
  }
}

void RunTables::declare(dynamics::SimulationOutput& output) {
  for (const dynamics::TablePlan& table : tables_) index_.push_back(output.add_table(table.name, table.header));
}

void RunTables::write(mjData* data, dynamics::SimulationOutput& output) {
  const mjModel* m = model_;
  mj_forward(m, data);
  // cacc, for mj_objectAcceleration; MuJoCo's recursion starts from the world's acceleration
  // set to -gravity, so its linear accelerations hold -g, added back below.
  mj_rnePostConstraint(m, data);
  const double t = data->time;
  size_t table = 0;
  for (const int b : bodies_) {
    mjtNum velocity[6], acceleration[6];  // [angular; linear] at the body frame's origin, world axes
    mj_objectVelocity(m, data, mjOBJ_XBODY, b, velocity, 0);
    mj_objectAcceleration(m, data, mjOBJ_XBODY, b, acceleration, 0);
    row_.assign({t});
    row_.insert(row_.end(), data->xpos + 3 * b, data->xpos + 3 * b + 3);
    row_.insert(row_.end(), data->xquat + 4 * b, data->xquat + 4 * b + 4);
    row_.insert(row_.end(), velocity + 3, velocity + 6);
    row_.insert(row_.end(), velocity, velocity + 3);
    for (int i = 0; i < 3; ++i) row_.push_back(acceleration[3 + i] + m->opt.gravity[i]);
    row_.insert(row_.end(), acceleration, acceleration + 3);
    output.write_row(index_[table++], row_);
  }

  // MuJoCo computes its energies only with mjENBL_ENERGY set; set here for these two calls
  // alone, so that the steps do not pay for them.
  const int flags = model_->opt.enableflags;
  model_->opt.enableflags |= mjENBL_ENERGY;
  mj_energyPos(m, data);
  mj_energyVel(m, data);
  model_->opt.enableflags = flags;
  const double kinetic = data->energy[1];
  const double potential = data->energy[0] + clearance_.potential_energy(data);
  const double total = kinetic + potential;
  const double energy[] = {t, kinetic, potential, total};
  output.write_row(index_[table++], energy);
  if (first_row_) initial_energy_ = total;
  first_row_ = false;
  max_energy_change_ = std::max(max_energy_change_, std::abs(total - initial_energy_));

  for (int k = 0; k < clearance_.count(); ++k) {
    row_.assign(tables_[table].header.size(), 0.0);
    row_[0] = t;
    clearance_.record_outputs(k, data, std::span<double>(row_).subspan(1));
    output.write_row(index_[table++], row_);
  }
}

}  // namespace clearjoint::mujoco_tool
