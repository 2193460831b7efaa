// SPDX-License-Identifier: BSD-3-Clause
// The table of every enum the package shows: the Python member names, their codes (the C++
// values, which array results hold as int8) and their docstrings.

#include "enum_codes.hpp"

#include "bindings.hpp"

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

namespace py = pybind11;

namespace clearjoint::python {

namespace {

namespace geo = clearjoint::geometry;

template <typename E>
struct Member {
  const char* name;
  E value;
  const char* doc = "";
};

class EnumTables {
 public:
  /// Add E's table; its members must be every code from 0 up, in order.
  template <typename E>
  EnumTables& add(const char* doc, std::initializer_list<Member<E>> members) {
    py::list rows;
    int code = 0;
    for (const Member<E>& m : members) {
      if (static_cast<int>(m.value) != code++) {
        throw std::logic_error(std::string(PythonEnum<E>::name) + "." + m.name + ": out of order");
      }
      rows.append(py::make_tuple(m.name, static_cast<int>(m.value), m.doc));
    }
    if (code != PythonEnum<E>::count) {
      throw std::logic_error(std::string(PythonEnum<E>::name) + ": PythonEnum's count is stale");
    }
    tables_.append(py::make_tuple(PythonEnum<E>::name, doc, rows));
    return *this;
  }
  py::list list() const { return tables_; }

 private:
  py::list tables_;
};

py::list enum_tables() {
  using S = geo::ContactScenario;
  using R = geo::CertificateReason;
  EnumTables tables;
  tables.add<geo::Certainty>(
      "Trust in an answer, strongest first. Array results hold these codes as int8.",
      {{"exact", geo::Certainty::exact, "decided with exact rational arithmetic"},
       {"certified", geo::Certainty::certified, "proved in floating point with rigorous error bounds"},
       {"uncertain", geo::Certainty::uncertain, "not proved; the certificate's reason says why"}});
  tables.add<R>(
      "Why an answer is uncertain, or, for an exact one, why the floating-point tiers did not "
      "decide it; none for certified answers. Array results hold these codes as int8. "
      "certificate_reason_text(code) gives the sentence.",
      {{"none", R::none},
       {"not_decided", R::not_decided},
       {"certificate_switched_off", R::certificate_switched_off},
       {"plane_filter_undecided", R::plane_filter_undecided},
       {"plane_filter_undecided_exact_fallback_off", R::plane_filter_undecided_exact_fallback_off},
       {"plane_results_not_representable", R::plane_results_not_representable},
       {"subdivision_budget_exhausted", R::subdivision_budget_exhausted},
       {"more_than_four_roots", R::more_than_four_roots},
       {"interval_proof_failed_near_multiple_root", R::interval_proof_failed_near_multiple_root},
       {"coefficient_overflow", R::coefficient_overflow},
       {"cylinder_points_not_representable", R::cylinder_points_not_representable},
       {"exact_root_isolation_budget_exhausted", R::exact_root_isolation_budget_exhausted},
       {"exact_coefficients_too_large", R::exact_coefficients_too_large},
       {"exact_intermediate_beyond_double_range", R::exact_intermediate_beyond_double_range},
       {"contact_not_representable_in_world", R::contact_not_representable_in_world},
       {"axes_parallel_within_tolerance", R::axes_parallel_within_tolerance},
       {"beyond_model_undecided", R::beyond_model_undecided}});
  tables.add<S>(
      "The contact scenarios of the paper's Fig. 2: (a)-(i) misaligned axes, (j)-(l) parallel "
      "axes, plus none (free flight) and beyond_model. Array results hold these codes as int8; "
      "scenario_label(code) gives the label.",
      {{"none", S::none, "free flight: no contact"},
       {"single_radial", S::single_radial, "(a) one rim against the wall"},
       {"single_axial", S::single_axial, "(b) one rim against a base"},
       {"radial_at_both_bases", S::radial_at_both_bases, "(c) both rims against the wall"},
       {"axial_at_both_bases", S::axial_at_both_bases, "(d) each rim against its base"},
       {"radial_and_axial_same_base", S::radial_and_axial_same_base,
        "(e) one rim against the wall and the base on its side"},
       {"radial_and_axial_opposite_bases", S::radial_and_axial_opposite_bases,
        "(f) one rim against the wall, the other against its base"},
       {"two_radial_one_axial", S::two_radial_one_axial, "(g) both rims against the wall, one against a base"},
       {"one_radial_two_axial", S::one_radial_two_axial, "(h) one rim against the wall, both against their bases"},
       {"all_four", S::all_four, "(i) both rims against wall and bases"},
       {"line", S::line, "(j) parallel axes, journal along the wall"},
       {"face", S::face, "(k) parallel axes, journal base on a bearing base"},
       {"line_and_face", S::line_and_face, "(l) (j) and (k) together"},
       {"beyond_model", S::beyond_model,
        "a configuration the paper's model does not cover (four wall crossings on a rim, a rim "
        "wholly beyond a surface, a penetration deeper than the clearance)"}});
  tables.add<geo::ContactType>(
      "What a contact is against. Array results hold these codes as int8.",
      {{"radial", geo::ContactType::radial, "against the lateral wall (eqs. 16-21; line: eqs. 6-8)"},
       {"axial", geo::ContactType::axial, "against a base (eqs. 11-15; face: eqs. 9-10)"}});
  tables.add<geo::ContactBase>(
      "Where a contact is. Array results hold these codes as int8.",
      {{"a", geo::ContactBase::a, "at bearing base A (eq. 3) and the journal rim facing it"},
       {"b", geo::ContactBase::b, "at bearing base B (eq. 4) and the journal rim facing it"},
       {"mid", geo::ContactBase::mid, "the journal's mid-length (line contact)"}});
  tables.add<geo::CirclePlaneTopology>(
      "How a circle meets a plane. Array results hold these codes as int8.",
      {{"disjoint", geo::CirclePlaneTopology::disjoint, "no common point; side says where the circle is"},
       {"tangent", geo::CirclePlaneTopology::tangent, "one common point of multiplicity 2"},
       {"two_crossings", geo::CirclePlaneTopology::two_crossings, "the circle passes through the plane"},
       {"circle_in_plane", geo::CirclePlaneTopology::circle_in_plane, "every rim point lies in the plane"}});
  tables.add<geo::CircleCylinderTopology>(
      "How a circle meets a cylinder's lateral surface. Array results hold these codes as int8.",
      {{"inside", geo::CircleCylinderTopology::inside, "every rim point strictly inside the wall"},
       {"outside", geo::CircleCylinderTopology::outside, "every rim point strictly beyond the wall"},
       {"crossing", geo::CircleCylinderTopology::crossing, "1 to 4 distinct common points"},
       {"on_surface", geo::CircleCylinderTopology::on_surface, "coaxial with equal radii"}});
  return tables.list();
}

}  // namespace

py::object python_enum_class(const char* name) {
  // Looked up with the GIL held, by which time the package has imported clearjoint._enums (or
  // the import happens here). A plain pointer, not a function-local static object: a static's
  // initialisation guard could deadlock against the GIL if the import released it.
  static PyObject* module = nullptr;
  if (module == nullptr) module = py::module_::import("clearjoint._enums").release().ptr();
  return py::handle(module).attr(name);
}

int enum_code(const py::handle& value, const char* argument, const char* enum_name, int count) {
  const std::string shown = std::string(argument) + " = " + std::string(py::repr(value));
  py::object code;
  if (!PyBool_Check(value.ptr())) code = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!code) {
    PyErr_Clear();
    throw py::type_error(shown + ": must be a " + enum_name + " or its integer code");
  }
  if (code < py::int_(0) || !(code < py::int_(count))) {
    throw py::value_error(shown + ": not a " + enum_name + " code (0 to " + std::to_string(count - 1) + ")");
  }
  return code.cast<int>();
}

void bind_enum_tables(py::module_& module) {
  module.def("_enum_tables", &enum_tables,
             "[(class name, docstring, [(member, code, docstring), ...]), ...] for clearjoint/_enums.py.");
}

}  // namespace clearjoint::python
