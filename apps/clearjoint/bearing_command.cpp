// SPDX-License-Identifier: BSD-3-Clause
// clearjoint bearing: the handbook characteristics of a plain journal bearing
// (lubrication::bearing_characteristics; clearjoint.lubrication.bearing_characteristics in Python)
// as one JSON object.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "clearjoint/lubrication/result_fields.hpp"
#include "commands.hpp"
#include "result_json.hpp"

namespace clearjoint::app {

namespace {

constexpr const char* kUsage =
    "usage: clearjoint bearing --eccentricity-ratio EPS --width-ratio B/D [--motion rotation|squeeze]\n"
    "                          [--method grid|short|long] [--cavitation half_sommerfeld|mass_conserving]\n"
    "                          [--grid NTHETAxNZ]\n"
    "  Prints one JSON object: the Sommerfeld number So = F psi^2 / (B D eta omega) (psi = c / R;\n"
    "  for squeeze, d eps / dt in place of omega), the attitude angle [rad] from the load to the\n"
    "  line of centres, the side-flow variable 2 pi Q_s / (R c omega B), p_max / (F / (B D)), and\n"
    "  what was solved. Defaults: rotation, grid 96x24; cavitation mass_conserving for the grid\n"
    "  (fed along the thickest film, as Raimondi & Boyd's tables), half_sommerfeld for short and\n"
    "  long. Exit status 2 for a usage error, 1 for a value out of range (the message names it).\n"
    "  docs/lubrication.md describes the models and their accuracy.\n";

int usage_error(const std::string& message) {
  std::fprintf(stderr, "clearjoint bearing: %s\n%s", message.c_str(), kUsage);
  return 2;
}

/// A whole-text number, or nullopt.
std::optional<double> number(const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') return std::nullopt;
  return value;
}

/// "96x24" as (96, 24), or nullopt.
std::optional<std::pair<int, int>> grid_size(const char* text) {
  int around = 0, across = 0, used = 0;
  if (std::sscanf(text, "%dx%d%n", &around, &across, &used) != 2 || text[used] != '\0') return std::nullopt;
  return std::make_pair(around, across);
}

}  // namespace

int run_bearing(Arguments args) {
  std::optional<double> eps, width_ratio;
  std::string motion = "rotation", method = "grid";
  std::optional<std::string> cavitation;
  std::optional<std::pair<int, int>> grid;
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string arg = args[k];
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (k + 1 == args.size()) return usage_error(arg + " needs a value (or is not an option)");
    const char* text = args[++k];
    if (arg == "--eccentricity-ratio" || arg == "--width-ratio") {
      const std::optional<double> value = number(text);
      if (!value) return usage_error(arg + " = '" + text + "': must be a number");
      (arg == "--width-ratio" ? width_ratio : eps) = value;
    } else if (arg == "--motion") {
      motion = text;
    } else if (arg == "--method") {
      method = text;
    } else if (arg == "--cavitation") {
      cavitation = text;
    } else if (arg == "--grid") {
      grid = grid_size(text);
      if (!grid) return usage_error(arg + " = '" + text + "': must be NTHETAxNZ, e.g. 96x24");
    } else {
      return usage_error("unknown option '" + arg + "'");
    }
  }
  if (!eps) return usage_error("--eccentricity-ratio is missing");
  if (!width_ratio) return usage_error("--width-ratio is missing");

  // From here on a value is wrong, not the call: InvalidInput, naming it, exits 1 (main.cpp).
  const lubrication::BearingCharacteristicsQuery query = lubrication::query_from_names(
      *eps, *width_ratio, {.motion = motion, .method = method, .cavitation = cavitation, .grid = grid});
  const lubrication::BearingCharacteristics r = lubrication::bearing_characteristics(query);
  const bool on_grid = query.method == lubrication::BearingMethod::grid;
  Json out;
  out["eccentricity_ratio"] = query.eccentricity_ratio;
  out["width_ratio"] = query.width_ratio;
  out["motion"] = lubrication::to_string(query.motion);
  out["method"] = lubrication::to_string(query.method);
  out["cavitation"] = lubrication::to_string(query.cavitation);
  out["grid"] = on_grid ? nlohmann::ordered_json::array({query.grid.circumferential_cells, query.grid.axial_cells})
                        : nlohmann::ordered_json(nullptr);
  write_result(r, ResultStyle::intersect, out);
  std::printf("%s\n", out.dump().c_str());
  return 0;
}

}  // namespace clearjoint::app
