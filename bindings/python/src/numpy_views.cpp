// SPDX-License-Identifier: BSD-3-Clause
#include "numpy_views.hpp"

#include <string>
#include <thread>

namespace py = pybind11;

namespace clearjoint::python {

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

DoubleArray as_doubles(const py::handle& value, const char* name) {
  DoubleArray array = DoubleArray::ensure(value);
  if (!array) {
    throw py::type_error(std::string(name) + ": must be numbers (an array of float), got " +
                         std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return array;
}

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t k = 0; k < array.ndim(); ++k) {
    text += std::to_string(array.shape(k)) + (array.ndim() == 1 ? "," : k + 1 < array.ndim() ? ", " : "");
  }
  return text + ")";
}

}  // namespace

BroadcastRows::BroadcastRows(const py::handle& value, const char* name, std::size_t row_width)
    : array_(as_doubles(value, name)), row_width_(row_width), name_(name) {
  // A vector row has one axis of length 3; a scalar row has none.
  const bool vector = row_width == 3;
  const py::ssize_t row_axes = vector ? 1 : 0;
  const auto row_fits = [&](py::ssize_t axis) { return !vector || array_.shape(axis) == 3; };
  if (array_.ndim() == row_axes && row_fits(0)) {
    batched_ = false;
  } else if (array_.ndim() == row_axes + 1 && row_fits(1)) {
    batched_ = true;
    rows_ = static_cast<std::size_t>(array_.shape(0));
  } else {
    throw py::value_error(std::string(name) + ": shape " + shape_text(array_) +
                          (vector ? " must be (3,) or (N, 3)" : " must be () or (N,)"));
  }
  data_ = array_.data();
}

void throw_length_mismatch(const char* first, std::size_t first_rows, const char* second,
                           std::size_t second_rows) {
  throw py::value_error(std::string(second) + " has " + std::to_string(second_rows) + " rows and " +
                        first + " " + std::to_string(first_rows) +
                        ": batched arguments must have the same length N (a single row broadcasts)");
}

std::string argument_message(const std::string& library_message, std::size_t row,
                             std::initializer_list<FieldName> fields) {
  for (const FieldName& field : fields) {
    const std::string prefix(field.library);
    // Followed by " =": "cylinder.axis" must not match "cylinder.axis_point = ...".
    if (library_message.compare(0, prefix.size() + 2, prefix + " =") == 0) {
      return field.argument + (field.batched ? "[" + std::to_string(row) + "]" : std::string()) +
             library_message.substr(prefix.size());
    }
  }
  return "row " + std::to_string(row) + ": " + library_message;
}

unsigned thread_count(const py::object& threads) {
  if (threads.is_none()) return std::max(1u, std::thread::hardware_concurrency());
  if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads)) {
    throw py::type_error("threads = " + std::string(py::repr(threads)) + ": must be an int or None");
  }
  const long long count = threads.cast<long long>();
  if (count < 1) throw py::value_error("threads = " + std::to_string(count) + ": must be at least 1");
  return static_cast<unsigned>(std::min<long long>(count, 1024));
}

}  // namespace clearjoint::python
