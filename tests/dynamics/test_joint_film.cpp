// SPDX-License-Identifier: BSD-3-Clause
// The oil film of a lubricated clearance joint (joint_film.cpp), seen through the joint: the
// force at one instant against the closed forms it is built on, where it acts, the regime switch,
// the force table's columns, and the energy balance of an integrated run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/lubrication/long_bearing.hpp"
#include "clearjoint/lubrication/short_bearing.hpp"

namespace clearjoint::dynamics {
namespace {

// Table 2 joint (the defaults of ClearanceJointParameters): Rj = 9.9 mm, Lj = 19.8 mm in a 20 mm
// bearing, radial clearance 0.1 mm.
constexpr double kClearance = 1e-4;
constexpr double kJournalRadius = 0.0099;
constexpr double kFilmWidth = 0.0198;  // the journal's length, centred in the bearing
constexpr double kViscosity = 0.04;    // Pa s, ISO VG 46 at 40 C
constexpr double kLimit = 2e-6;        // m, h_l
constexpr double kSpin = 100.0;        // rad/s

constexpr BodyIndex kBearing = 0;
constexpr BodyIndex kJournal = 1;
constexpr std::array<double, kContactSlotCount + 1> kNoMemory{};

ClearanceJointParameters lubricated(FilmMethod method) {
  ClearanceJointParameters p;
  p.normal.model = NormalForceModel::hertz;
  p.friction.coefficient = 0.0;
  JointLubrication l;
  l.viscosity = kViscosity;
  l.method = method;
  l.film_thickness_limit = kLimit;
  l.transition_width = kLimit;
  p.lubrication = l;
  return p;
}

/// Bearing (body 0) at the origin, axis z; journal (body 1) with P_j at its mass centre, axis z.
ClearanceRevoluteJoint make_joint(const ClearanceJointParameters& p) {
  return ClearanceRevoluteJoint("joint", {kBearing, Vector3::Zero(), Vector3::UnitZ()},
                                {kJournal, Vector3::Zero(), Vector3::UnitZ()}, p);
}

/// The bearing at rest; the journal at `p_WPj`, moving at `v_W`, spinning at `spin` about z.
SystemKinematics journal_at(const Vector3& p_WPj, const Vector3& v_W = Vector3::Zero(),
                            double spin = kSpin) {
  SystemKinematics k(2);
  k.set(kBearing, BodyState{});
  BodyState journal;
  journal.position_W = p_WPj;
  journal.velocity_W = v_W;
  journal.angular_velocity_B = Vector3(0.0, 0.0, spin);
  k.set(kJournal, journal);
  return k;
}

JointFilmState film_at(const ClearanceRevoluteJoint& joint, const SystemKinematics& k) {
  const ClearanceJointState state = joint.evaluate(0.0, k, kNoMemory);
  EXPECT_TRUE(state.film.has_value());
  return state.film.value_or(JointFilmState{});
}

// eps from the exact film geometry (journal_offset through the parts' poses): a few ulps of the
// 1e-2 m radii in 1e-4 m of clearance, 1e-14 relative; 1e-12 bounds it.
constexpr double kExactGeometryRounding = 1e-12;

constexpr FilmMethod kMethods[] = {FilmMethod::short_bearing, FilmMethod::long_bearing,
                                   FilmMethod::grid};

// A centred journal spinning in a uniform film meets no wedge: no force. The grid's film comes
// from the exact thickness, uniform to rounding (1e-16 of R), so its force is a rounding residue;
// 1e-9 of the force at eps = 0.5 bounds it with room.
constexpr double kCentredResidue = 1e-9;

TEST(JointFilm, CarriesNoForceAtTheCentreWithoutSqueeze) {
  for (FilmMethod method : kMethods) {
    const ClearanceRevoluteJoint joint = make_joint(lubricated(method));
    const double reference =
        film_at(joint, journal_at(Vector3(0.5 * kClearance, 0.0, 0.0))).force_on_journal_W.norm();
    const JointFilmState centred = film_at(joint, journal_at(Vector3::Zero()));
    EXPECT_GT(reference, 0.0);
    EXPECT_EQ(centred.regime, FilmRegime::film);
    EXPECT_LE(centred.force_on_journal_W.norm(), kCentredResidue * reference) << lubrication::to_string(method);
    EXPECT_LE(centred.moment_on_journal_W.norm(), kCentredResidue * reference * kFilmWidth);
    EXPECT_EQ(centred.eccentricity_ratio, 0.0);
  }
}

// The film pushes the journal back towards the centre and, spinning positively, 90 degrees or
// less ahead (beta in (0, pi/2]); reversing the spin mirrors the tangential part.
TEST(JointFilm, PushesTheJournalBackAndTurnsItsSideWithTheSpin) {
  for (FilmMethod method : kMethods) {
    const ClearanceRevoluteJoint joint = make_joint(lubricated(method));
    const Vector3 offset(0.5 * kClearance, 0.0, 0.0);
    const JointFilmState ahead = film_at(joint, journal_at(offset, Vector3::Zero(), kSpin));
    const JointFilmState behind = film_at(joint, journal_at(offset, Vector3::Zero(), -kSpin));
    EXPECT_LT(ahead.force_on_journal_W.x(), 0.0) << lubrication::to_string(method);
    EXPECT_GT(ahead.force_on_journal_W.y(), 0.0) << lubrication::to_string(method);
    EXPECT_GT(ahead.attitude_angle, 0.0);
    EXPECT_LE(ahead.attitude_angle, 0.5 * std::numbers::pi);
    EXPECT_NEAR(behind.force_on_journal_W.x(), ahead.force_on_journal_W.x(),
                1e-9 * ahead.force_on_journal_W.norm());
    EXPECT_NEAR(behind.force_on_journal_W.y(), -ahead.force_on_journal_W.y(),
                1e-9 * ahead.force_on_journal_W.norm());
    EXPECT_NEAR(behind.attitude_angle, -ahead.attitude_angle, 1e-9);
    EXPECT_NEAR(ahead.eccentricity_ratio, 0.5, kExactGeometryRounding);
  }
}

// The closed-form joint is the closed form at the film's mid-plane: eps, its rate and the whirl
// of the line of centres from the journal's pose and velocity relative to the bearing. Off the
// axes, with squeeze and whirl, the joint must give the closed form's load in the frame
// (e_hat, t_hat) to rounding.
TEST(JointFilm, IsTheClosedFormInTheFrameOfTheLineOfCentres) {
  const Vector3 offset(0.3 * kClearance, 0.4 * kClearance, 0.0);  // eps = 0.5
  const Vector3 velocity(0.002, -0.001, 0.0);                      // m/s, squeeze and whirl
  const Vector3 e_hat = offset.normalized(), t_hat = Vector3::UnitZ().cross(e_hat);
  lubrication::PlanarFilmState planar;
  planar.eccentricity_ratio = 0.5;
  planar.eccentricity_ratio_rate = velocity.dot(e_hat) / kClearance;
  planar.line_of_centres_rate = velocity.dot(t_hat) / offset.norm();
  planar.journal_spin = kSpin;
  const lubrication::PlanarBearing bearing{kJournalRadius, kFilmWidth, kClearance};
  for (FilmMethod method : {FilmMethod::short_bearing, FilmMethod::long_bearing}) {
    const lubrication::PlanarFilmLoad expected =
        method == FilmMethod::short_bearing
            ? lubrication::short_bearing_load(bearing, planar, kViscosity)
            : lubrication::long_bearing_load(bearing, planar, kViscosity);
    const JointFilmState film = film_at(make_joint(lubricated(method)), journal_at(offset, velocity));
    const double scale = expected.magnitude;
    EXPECT_NEAR(film.force_on_journal_W.dot(e_hat), expected.radial, 1e-9 * scale);
    EXPECT_NEAR(film.force_on_journal_W.dot(t_hat), expected.tangential, 1e-9 * scale);
    EXPECT_NEAR(film.force_on_journal_W.z(), 0.0, 1e-12 * scale);
    EXPECT_NEAR(film.attitude_angle, expected.attitude_angle, 1e-9);
    EXPECT_NEAR(film.max_pressure, expected.max_pressure, 1e-9 * expected.max_pressure);
    EXPECT_NEAR(film.min_thickness, 0.5 * kClearance, 1e-3 * kClearance);  // first order in c / R
  }
}

// Applied at P_j on the journal, the opposite on the bearing at the same point: the pair works at
// F . v_BJ + M . omega_BJ, the rate written for W_film.
TEST(JointFilm, ActsAtTheJournalCentreAndWritesItsPowerAsTheRateOfItsWork) {
  const ClearanceRevoluteJoint joint = make_joint(lubricated(FilmMethod::grid));
  const Vector3 velocity(-0.001, 0.003, 0.0);
  const SystemKinematics k = journal_at(Vector3(0.4 * kClearance, -0.2 * kClearance, 0.0), velocity);
  GeneralisedForces forces(k);
  std::array<double, kContactSlotCount + 1> rate{};
  joint.add_forces({0.0, k, kNoMemory, rate}, forces);
  const JointFilmState film = film_at(joint, k);
  EXPECT_EQ(forces.force_W(kJournal), film.force_on_journal_W);
  EXPECT_EQ(forces.force_W(kBearing), -film.force_on_journal_W);
  EXPECT_EQ(forces.moment_W(kJournal), film.moment_on_journal_W);
  EXPECT_DOUBLE_EQ(rate[kFilmWorkIndex],
                   film.force_on_journal_W.dot(velocity) +
                       film.moment_on_journal_W.dot(Vector3(0.0, 0.0, kSpin)));
  for (int slot = 0; slot < kContactSlotCount; ++slot) EXPECT_EQ(rate[slot], 0.0);
}

/// Largest change of the joint's total force between neighbours, walking the journal outwards
/// along x in `steps` equal steps so that h_min goes from h_l + 2 w to -h_l (into dry contact).
double largest_jump(const ClearanceRevoluteJoint& joint, int steps, std::vector<FilmRegime>* regimes) {
  const double first = kClearance - 3.0 * kLimit, last = kClearance + kLimit;
  Vector3 previous = Vector3::Zero();
  double jump = 0.0;
  for (int s = 0; s <= steps; ++s) {
    const double e = first + (last - first) * s / steps;
    const SystemKinematics k = journal_at(Vector3(e, 0.0, 0.0));
    const ClearanceJointState state = joint.evaluate(0.0, k, kNoMemory);
    if (s > 0) jump = std::max(jump, (state.force_on_journal_W - previous).norm());
    previous = state.force_on_journal_W;
    if (regimes != nullptr) regimes->push_back(state.film->regime);
  }
  return jump;
}

// The joint's force is continuous through the band and into dry contact: halving the step
// halves the largest jump between neighbours (a discontinuity would keep it). Along the way the
// regimes come in the order film, blend, dry.
TEST(JointFilm, PassesContinuouslyFromTheFilmToDryContact) {
  for (FilmMethod method : {FilmMethod::short_bearing, FilmMethod::grid}) {
    const ClearanceRevoluteJoint joint = make_joint(lubricated(method));
    std::vector<FilmRegime> regimes;
    const double coarse = largest_jump(joint, 200, &regimes);
    const double fine = largest_jump(joint, 400, nullptr);
    std::printf("%s: largest jump %.4g N at 200 steps, %.4g N at 400\n",
                std::string(lubrication::to_string(method)).c_str(), coarse, fine);
    EXPECT_LT(fine, 0.6 * coarse) << lubrication::to_string(method);
    EXPECT_EQ(regimes.front(), FilmRegime::film);
    EXPECT_EQ(regimes.back(), FilmRegime::dry);
    for (size_t k = 1; k < regimes.size(); ++k) {
      const auto rank = [](FilmRegime r) { return r == FilmRegime::film ? 0 : r == FilmRegime::blend ? 1 : 2; };
      EXPECT_LE(rank(regimes[k - 1]), rank(regimes[k]));
    }
    EXPECT_NE(std::find(regimes.begin(), regimes.end(), FilmRegime::blend), regimes.end());
  }
}

// Between h_l and the wall neither the film nor the dry law acts; the dry law takes over from 0.
TEST(JointFilm, LeavesTheJointFreeBetweenTheLimitAndTheWall) {
  const ClearanceRevoluteJoint joint = make_joint(lubricated(FilmMethod::short_bearing));
  const ClearanceJointState gap =
      joint.evaluate(0.0, journal_at(Vector3(kClearance - 0.5 * kLimit, 0.0, 0.0)), kNoMemory);
  EXPECT_EQ(gap.film->regime, FilmRegime::dry);
  EXPECT_EQ(gap.force_on_journal_W, Vector3::Zero());
  EXPECT_TRUE(std::isnan(gap.film->max_pressure));
  const ClearanceJointState contact =
      joint.evaluate(0.0, journal_at(Vector3(kClearance + 1e-6, 0.0, 0.0)), kNoMemory);
  EXPECT_EQ(contact.contacts.contact_count, 1);
  EXPECT_LT(contact.force_on_journal_W.x(), 0.0);
}

TEST(JointFilm, AddsItsColumnsAndItsWorkOnlyToALubricatedJoint) {
  ClearanceJointParameters dry = lubricated(FilmMethod::short_bearing);
  dry.lubrication.reset();
  const ClearanceRevoluteJoint dry_joint = make_joint(dry);
  const ClearanceRevoluteJoint oiled = make_joint(lubricated(FilmMethod::short_bearing));
  EXPECT_EQ(dry_joint.extra_state_count(), kContactSlotCount);
  EXPECT_EQ(oiled.extra_state_count(), kContactSlotCount + 1);
  const std::vector<std::string> dry_columns = dry_joint.output_columns();
  std::vector<std::string> expected = dry_columns;
  for (const char* c : {"film.min_thickness", "film.max_pressure", "film.eccentricity_ratio",
                        "film.attitude_angle", "film.regime", "film.weight", "film.work"}) {
    expected.push_back(c);
  }
  EXPECT_EQ(oiled.output_columns(), expected);
  EXPECT_FALSE(dry_joint.evaluate(0.0, journal_at(Vector3::Zero()), kNoMemory).film.has_value());
  std::vector<double> values(expected.size());
  const std::array<double, kContactSlotCount + 1> memory{0, 0, 0, 0, 0, 1.25};
  oiled.record_outputs(0.0, journal_at(Vector3(0.5 * kClearance, 0.0, 0.0)), memory, values);
  EXPECT_NEAR(values[values.size() - 5], 0.5, kExactGeometryRounding);  // eccentricity ratio
  EXPECT_EQ(values[values.size() - 3], 1.0);          // regime: film
  EXPECT_EQ(values.back(), 1.25);                     // W_film, from the extra state
}

TEST(JointFilm, RefusesBadInputNamingTheJointsField) {
  ClearanceJointParameters p = lubricated(FilmMethod::grid);
  p.lubrication->viscosity = -1.0;
  try {
    make_joint(p);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), "joint.lubrication.viscosity = -1: must be positive");
  }
}

// The table's film force against the grid's it tabulates (issue 49): within 0.5 % at every
// sampled state of the Table 2 joint, spin, squeeze (approach and separation) and whirl mixed,
// eps from 0.05 to 0.97. The table's own measured bound (film_table.hpp) is below it.
constexpr double kTableForceTolerance = 5e-3;

TEST(JointFilm, TabledStaysWithinHalfAPercentOfTheGridAtSampledStates) {
  const ClearanceRevoluteJoint table = make_joint(lubricated(FilmMethod::table));
  const ClearanceRevoluteJoint grid = make_joint(lubricated(FilmMethod::grid));
  double worst = 0.0;
  for (const double eps : {0.05, 0.3, 0.6, 0.81, 0.9, 0.97}) {
    for (int k = 0; k < 12; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / 12.0;
      const Vector3 offset = eps * kClearance * Vector3(std::cos(angle), std::sin(angle), 0.0);
      // A velocity of 0.02 m/s at angle 3 k (approach, separation, whirl either way).
      const Vector3 velocity = 0.02 * Vector3(std::cos(3.0 * angle + 1.0), std::sin(3.0 * angle + 1.0), 0.0);
      const double spin = k % 3 == 0 ? -kSpin : kSpin;
      const SystemKinematics state = journal_at(offset, velocity, spin);
      const Vector3 tabulated = film_at(table, state).force_on_journal_W;
      const Vector3 solved = film_at(grid, state).force_on_journal_W;
      ASSERT_GT(solved.norm(), 0.0);
      const double error = (tabulated - solved).norm() / solved.norm();
      worst = std::max(worst, error);
      EXPECT_LE(error, kTableForceTolerance) << "eps " << eps << " angle " << angle;
    }
  }
  RecordProperty("worst_relative_force_difference", std::to_string(worst));
  std::printf("table against grid, worst relative force difference: %.3g\n", worst);
}

/// The lubricated Section 6.1 slider-crank with its joint's film solved by `method`.
ModelDescription lubricated_section61(FilmMethod method) {
  ModelDescription model = read_model_file(std::string(CLEARJOINT_MODELS_DIR) +
                                           "/slider_crank_planar_clearance_lubricated.json");
  for (ForceDescription& force : model.forces) {
    if (auto* joint = std::get_if<ClearanceRevoluteDescription>(&force)) joint->parameters.lubrication->method = method;
  }
  return model;
}

const ClearanceRevoluteJoint& clearance_joint_of(const MultibodySystem& system, size_t& index) {
  for (index = 0; index < system.force_elements().size(); ++index) {
    if (const auto* joint = dynamic_cast<const ClearanceRevoluteJoint*>(system.force_elements()[index].get())) {
      return *joint;
    }
  }
  throw std::logic_error("no clearance joint");
}

// Along the first 10 ms of the lubricated Section 6.1 run with the table (the start, where the
// journal leaves the centre and the film's load changes fastest), the grid's film force at every
// reported state is the table's within 0.5 %.
TEST(JointFilm, TabledStaysWithinHalfAPercentOfTheGridAlongTheLubricatedSection61Run) {
  const ModelDescription model = lubricated_section61(FilmMethod::table);
  BuiltModel table = build_model(model);
  const BuiltModel grid = build_model(lubricated_section61(FilmMethod::grid));
  size_t index = 0;
  const ClearanceRevoluteJoint& tabled = clearance_joint_of(*table.system, index);
  const ClearanceRevoluteJoint& solved = clearance_joint_of(*grid.system, index);
  IntegratorSettings settings = model.solver;
  settings.end_time = 0.01;
  settings.report_step = 1e-4;
  std::vector<double> y = table.initial_state;
  double worst = 0.0;
  int compared = 0;
  integrate(*table.system, y, settings, [&](double t, std::span<const double> state) {
    SystemKinematics k(static_cast<int>(table.system->bodies().size()));
    k.update(t, state);
    const std::span<const double> memory = table.system->extra_state(state, index);
    const ClearanceJointState a = tabled.evaluate(t, k, memory), b = solved.evaluate(t, k, memory);
    ASSERT_TRUE(a.film && b.film);
    const double size = b.film->force_on_journal_W.norm();
    if (size == 0.0) return;  // the centred start
    const double error = (a.film->force_on_journal_W - b.film->force_on_journal_W).norm() / size;
    worst = std::max(worst, error);
    ++compared;
    EXPECT_LE(error, kTableForceTolerance) << "t " << t;
  });
  EXPECT_GE(compared, 100);
  std::printf("along the run: %d states, worst relative film force difference %.3g\n", compared, worst);
}

/// The film solutions a joint's run summary counts ("... film: N solutions, ...").
long film_solutions(const ClearanceRevoluteJoint& joint) {
  const std::string text = joint.statistics_text();
  const size_t at = text.find(" film: ");
  EXPECT_NE(at, std::string::npos) << text;
  return at == std::string::npos ? -1 : std::stol(text.substr(at + 7));
}

// The impact memory's update after each accepted step reads the contacts only: the film is solved
// once per right-hand side (its force) and never again for the update.
TEST(JointFilm, IsSolvedOncePerRightHandSideAndNotForTheImpactMemory) {
  for (const FilmMethod method : {FilmMethod::short_bearing, FilmMethod::table}) {
    const ModelDescription model = lubricated_section61(method);
    BuiltModel built = build_model(model);
    size_t index = 0;
    const ClearanceRevoluteJoint& joint = clearance_joint_of(*built.system, index);
    IntegratorSettings settings = model.solver;
    settings.end_time = 1e-3;
    std::vector<double> y = built.initial_state;
    const IntegrationStatistics stats = integrate(*built.system, y, settings, {});
    EXPECT_GT(stats.steps, 10);
    EXPECT_EQ(film_solutions(joint), stats.derivative_calls) << "method " << static_cast<int>(method);
  }
}

TEST(JointFilm, TabledHandsATiltedJournalToTheGrid) {
  const ClearanceRevoluteJoint table = make_joint(lubricated(FilmMethod::table));
  const ClearanceRevoluteJoint grid = make_joint(lubricated(FilmMethod::grid));
  SystemKinematics state(2);
  state.set(kBearing, BodyState{});
  BodyState journal;
  journal.position_W = Vector3(0.5 * kClearance, 0.0, 0.0);
  journal.velocity_W = Vector3(0.0, 0.01, 0.0);
  journal.angular_velocity_B = Vector3(0.0, 0.0, kSpin);
  const double tilt = 0.5 * kClearance / kFilmWidth;  // the ends' offsets differ by 0.5 c
  journal.euler_parameters = Vector4(std::cos(0.5 * tilt), 0.0, std::sin(0.5 * tilt), 0.0);
  state.set(kJournal, journal);
  // The grid's half-Sommerfeld solve is one linear solve, the same from any first guess.
  const Vector3 solved = film_at(grid, state).force_on_journal_W;
  ASSERT_GT(solved.norm(), 0.0);
  EXPECT_EQ(film_at(table, state).force_on_journal_W, solved);
}

TEST(JointFilm, TabledHandsAJournalPartlyOutOfItsBearingToTheGrid) {
  const ClearanceRevoluteJoint table = make_joint(lubricated(FilmMethod::table));
  const ClearanceRevoluteJoint grid = make_joint(lubricated(FilmMethod::grid));
  // 0.5 mm along the axis: 0.4 mm of the journal's 19.8 mm is out of the 20 mm bearing, so the
  // film is narrower than the table's.
  const SystemKinematics state = journal_at(Vector3(0.5 * kClearance, 0.0, 5e-4), Vector3(0.0, 0.01, 0.0));
  const Vector3 solved = film_at(grid, state).force_on_journal_W;
  ASSERT_GT(solved.norm(), 0.0);
  EXPECT_EQ(film_at(table, state).force_on_journal_W, solved);
}

TEST(JointFilm, TabledRefusesTheMassConservingModelNamingTheField) {
  ClearanceJointParameters p = lubricated(FilmMethod::table);
  p.lubrication->cavitation = lubrication::CavitationModel::mass_conserving;
  p.lubrication->groove_direction_B = Vector3::UnitX();
  try {
    make_joint(p);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()),
              "joint.lubrication.cavitation = \"mass_conserving\": method table is half-Sommerfeld only; use method grid");
  }
}

const Vector3 kThrowVelocity(0.05, 0.02, 0.0);  // m/s
/// The energy the film can take: the journal's translation, 1/2 m v^2 (its spin about the axis
/// meets no pressure moment, so it keeps its 0.245 J).
const double kThrowEnergy = 0.5 * kThrowVelocity.squaredNorm();

/// A journal (1 kg, P_j at its mass centre, axis z) free in a grounded bearing, zero gravity,
/// thrown across the clearance while spinning: the film alone catches it.
ModelDescription thrown_journal(FilmMethod method) {
  ModelDescription model;
  model.name = "journal on its film";
  BodyDescription journal;
  journal.properties = {"journal", 1.0, Vector3(2.5e-5, 2.5e-5, 4.9e-5)};
  journal.initial.velocity_W = kThrowVelocity;
  journal.initial.angular_velocity_B = Vector3(0.0, 0.0, kSpin);
  model.bodies.push_back(journal);
  ClearanceJointParameters p = lubricated(method);
  p.lubrication->viscosity = 0.002;  // a light oil: the journal crosses most of the clearance
  model.forces.push_back(ClearanceRevoluteDescription{
      "clearance", {"ground", Vector3::Zero(), Vector3::UnitZ()},
      {"journal", Vector3::Zero(), Vector3::UnitZ()}, p});
  model.output_bodies = {"journal"};
  return model;
}

struct Balance {
  double worst = 0.0;  ///< max over report times of |E - E0 - W_film|, relative to kThrowEnergy
  double work = 0.0;         ///< W_film at the end, J
  double largest_eps = 0.0;  ///< of the film's mid-plane
};

Balance energy_balance(FilmMethod method, double tolerance) {
  BuiltModel built = build_model(thrown_journal(method));
  MultibodySystem& system = *built.system;
  std::vector<double> y = built.initial_state;
  const double E0 = system.kinetic_energy(y) + system.potential_energy(0.0, y);
  const size_t joint = system.force_elements().size() - 1;
  const auto& element = dynamic_cast<const ClearanceRevoluteJoint&>(*system.force_elements()[joint]);
  IntegratorSettings s;
  s.end_time = 0.02;
  s.report_step = 1e-4;
  s.relative_tolerance = s.absolute_tolerance = tolerance;
  Balance b;
  integrate(system, y, s, [&](double t, std::span<const double> state) {
    const double E = system.kinetic_energy(state) + system.potential_energy(t, state);
    const double work = system.extra_state(state, joint)[kFilmWorkIndex];
    b.worst = std::max(b.worst, std::abs(E - E0 - work) / kThrowEnergy);
    b.work = work;
    SystemKinematics k(1);
    k.update(t, state);
    const ClearanceJointState js = element.evaluate(t, k, system.extra_state(state, joint));
    b.largest_eps = std::max(b.largest_eps, js.film->eccentricity_ratio);
  });
  return b;
}

// E(t) - E(0) = W_film(t): the film's work, integrated with the motion, accounts for every joule
// the journal loses, to the integrator's tolerance, and 100 times tighter gives a balance at least
// 10 times closer.
TEST(JointFilm, BalancesTheEnergyLostAgainstTheFilmsWork) {
  const Balance coarse = energy_balance(FilmMethod::short_bearing, 1e-8);
  const Balance fine = energy_balance(FilmMethod::short_bearing, 1e-10);
  std::printf("W_film = %.6g J of %.3g J thrown (max eps %.3f); |E - E0 - W| / (thrown) = %.3g at "
              "1e-8, %.3g at 1e-10\n", fine.work, kThrowEnergy, fine.largest_eps, coarse.worst, fine.worst);
  EXPECT_LT(fine.work, -0.5 * kThrowEnergy);  // the film has taken most of the energy
  EXPECT_GT(fine.largest_eps, 0.5);     // having let the journal cross most of the clearance
  EXPECT_LT(fine.worst, 1e-6);
  EXPECT_LT(10.0 * fine.worst, coarse.worst);
}

}  // namespace
}  // namespace clearjoint::dynamics
