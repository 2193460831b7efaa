// SPDX-License-Identifier: BSD-3-Clause
// clearjoint bearing: the handbook characteristics of a plain journal bearing
// (lubrication::bearing_characteristics; clearjoint.lubrication.bearing_characteristics in Python)
// as one JSON object.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "clearjoint/lubrication/result_fields.hpp"
#include "commands.hpp"
#include "result_json.hpp"

namespace clearjoint::app {

namespace {

/// "a|b|c": E's keys, from its table, as the usage line lists choices.
template <geometry::TabledEnum E>
std::string choices() {
  std::string text;
  for (const geometry::EnumEntry<E>& entry : geometry::EnumTable<E>::entries) {
    if (!text.empty()) text += '|';
    text += entry.key;
  }
  return text;
}

std::string usage() {
  return "usage: clearjoint bearing --eccentricity-ratio EPS --width-ratio B/D [--motion " +
         choices<lubrication::BearingMotion>() + "]\n"
         "                          [--method " + choices<lubrication::BearingMethod>() + "] [--cavitation " +
         choices<lubrication::CavitationModel>() + "]\n"
         "                          [--grid NTHETAxNZ [--allow-large-grid]]\n"
         "  Prints one JSON object: the Sommerfeld number So = F psi^2 / (B D eta omega) (psi = c / R;\n"
         "  for squeeze, d eps / dt in place of omega), the attitude angle [rad] from the load to the\n"
         "  line of centres, the side-flow variable 2 pi Q_s / (R c omega B), p_max / (F / (B D)), and\n"
         "  what was solved. Defaults: rotation, grid 96x24; cavitation mass_conserving for the grid\n"
         "  (fed along the thickest film, as Raimondi & Boyd's tables), half_sommerfeld for short,\n"
         "  long and table (the grid's film tabulated over eps up to 0.98, built on first use and kept\n"
         "  in the file cache $CLEARJOINT_CACHE_DIR, else $XDG_CACHE_HOME/clearjoint, else\n"
         "  ~/.cache/clearjoint; CLEARJOINT_CACHE_DIR set and empty: no file cache). A grid whose\n"
         "  estimated cost is above the solver's limits (about half a second a solve) is refused\n"
         "  with the estimate unless --allow-large-grid is given. Each option once.\n"
         "  Exit status 2 for a usage error, 1 for a value out of range (the message names it).\n"
         "  docs/lubrication.md describes the models and their accuracy.\n";
}

int usage_error(const std::string& message) {
  std::fprintf(stderr, "clearjoint bearing: %s\n%s", message.c_str(), usage().c_str());
  return 2;
}

/// A whole-text number, or nullopt.
std::optional<double> number(const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') return std::nullopt;
  return value;
}

/// One count of "96x24": the whole text a decimal int, or nullopt (out of int's range too).
std::optional<int> cell_count(std::string_view text) {
  int count = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return count;
}

/// "96x24" as (96, 24), or nullopt.
std::optional<std::pair<int, int>> grid_size(std::string_view text) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const std::optional<int> around = cell_count(text.substr(0, x)), across = cell_count(text.substr(x + 1));
  if (!around || !across) return std::nullopt;
  return std::make_pair(*around, *across);
}

/// The library's message in the command line's terms: the field it starts with named as the
/// option that set it ("width_ratio = 1e+300: ..." -> "--width-ratio = 1e+300: ..."), and the
/// grid's cost override as the switch that gives it.
std::string in_option_terms(std::string message) {
  for (const std::string_view field : {"eccentricity_ratio", "width_ratio", "motion", "method", "cavitation", "grid"}) {
    if (message.starts_with(std::string(field) + " = ")) {
      std::string option = "--" + std::string(field);
      for (char& c : option) c = c == '_' ? '-' : c;
      message.replace(0, field.size(), option);
      break;
    }
  }
  constexpr std::string_view kOverride = "allow_large_grid";
  for (std::size_t at = message.find(kOverride); at != std::string::npos;
       at = message.find(kOverride, at + kOverride.size())) {
    message.replace(at, kOverride.size(), "--allow-large-grid");
  }
  return message;
}

/// Solves the query and prints its JSON object; exit status 0.
int answer(double eps, double width_ratio, const lubrication::BearingCharacteristicsNames& names) {
  const lubrication::BearingCharacteristicsQuery query = lubrication::query_from_names(eps, width_ratio, names);
  const lubrication::BearingCharacteristics r = lubrication::bearing_characteristics(query);
  const bool on_grid = query.method == lubrication::BearingMethod::grid ||
                       query.method == lubrication::BearingMethod::table;  // the grid it tabulates
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

}  // namespace

int run_bearing(Arguments args) {
  std::optional<double> eps, width_ratio;
  std::string motion = "rotation", method = "grid";
  std::optional<std::string> cavitation;
  std::optional<std::pair<int, int>> grid;
  bool allow_large_grid = false;
  std::map<std::string, std::string> given;  // option -> its text, to refuse a second one
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string arg = args[k];
    if (arg == "--help" || arg == "-h") {
      std::fputs(usage().c_str(), stdout);
      return 0;
    }
    const bool is_switch = arg == "--allow-large-grid";
    if (!is_switch && k + 1 == args.size()) return usage_error(arg + " needs a value (or is not an option)");
    const char* text = is_switch ? "" : args[++k];
    if (const auto [earlier, first] = given.emplace(arg, text); !first) {
      return usage_error(arg + " is given twice" +
                         (is_switch ? std::string() : " ('" + earlier->second + "', then '" + text + "')") +
                         ": give it once");
    }
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
      if (!grid) {
        return usage_error(arg + " = '" + text + "': must be NTHETAxNZ, two whole numbers up to " +
                           std::to_string(std::numeric_limits<int>::max()) + ", e.g. 96x24");
      }
    } else if (is_switch) {
      allow_large_grid = true;
    } else {
      return usage_error("unknown option '" + arg + "'");
    }
  }
  if (!eps) return usage_error("--eccentricity-ratio is missing");
  if (!width_ratio) return usage_error("--width-ratio is missing");

  // From here on a value is wrong, not the call: the library's InvalidInput, naming the option,
  // exits 1.
  try {
    return answer(*eps, *width_ratio,
                  {.motion = motion, .method = method, .cavitation = cavitation, .grid = grid,
                   .allow_large_grid = allow_large_grid});
  } catch (const geometry::InvalidInput& e) {
    std::fprintf(stderr, "clearjoint bearing: %s\n", in_option_terms(e.what()).c_str());
    return 1;
  }
}

}  // namespace clearjoint::app
