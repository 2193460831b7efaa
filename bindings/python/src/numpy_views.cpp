// SPDX-License-Identifier: BSD-3-Clause
#include "numpy_views.hpp"

#include <algorithm>
#include <string>
#include <thread>

namespace py = pybind11;

namespace clearjoint::python {

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// What a refused argument is, for messages: "an array of complex128", "NoneType", "list (dtype <U1)".
std::string description(const py::handle& value, const py::array& converted) {
  const std::string dtype = py::str(converted.dtype());
  if (py::isinstance<py::array>(value)) return "an array of " + dtype;
  const std::string type = py::str(py::type::of(value).attr("__name__"));
  return converted.ndim() == 0 || converted.dtype().kind() == 'O' ? type : type + " (dtype " + dtype + ")";
}

/// `value` as a NumPy array of integers or floats, the dtypes that mean numbers. NumPy would
/// also convert bools, complex numbers (dropping the imaginary part), datetimes (as day counts),
/// strings of digits and None (as nan); a masked array would lose its mask. Those are refused.
py::array numeric_array(const py::handle& value, const std::string& name) {
  const py::module_ masked = py::module_::import("numpy.ma");
  if (py::isinstance(value, masked.attr("MaskedArray"))) {
    if (py::bool_(masked.attr("is_masked")(value))) {
      throw py::value_error(name + ": a masked array with masked values; fill them (.filled()) or "
                            "drop their rows (numpy.ma.compress_rows) first");
    }
    return numeric_array(value.attr("data"), name);
  }
  const py::array array = py::array::ensure(value);
  if (!array) throw py::type_error(name + ": must be numbers (int or float), got " +
                                   std::string(py::str(py::type::of(value).attr("__name__"))));
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f') {
    throw py::type_error(name + ": must be numbers (int or float), got " + description(value, array));
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

/// `value` as C-contiguous float64. ensure() returns an empty handle, and clears NumPy's error,
/// when the copy cannot be made: a MemoryError, as for a broadcast view of 10^12 rows (no memory
/// of its own, 24 TB as a copy). Named here, instead of a crash on the empty handle.
DoubleArray as_doubles(const py::handle& value, const char* name) {
  const py::array numbers = numeric_array(value, name);
  DoubleArray doubles = DoubleArray::ensure(numbers);
  if (!doubles) [[unlikely]] {
    PyErr_Format(PyExc_MemoryError,
                 "%s: shape %s does not fit in memory as contiguous float64; pass fewer rows at a time",
                 name, shape_text(numbers).c_str());
    throw py::error_already_set();
  }
  return doubles;
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

std::string argument_message(const RowError& error, std::initializer_list<FieldName> fields) {
  for (const FieldName& field : fields) {
    if (error.invalid_input && error.field_path == field.library) {
      return field.argument + (field.batched ? "[" + std::to_string(error.row) + "]" : std::string()) +
             error.message.substr(error.field_path.size());
    }
  }
  return "row " + std::to_string(error.row) + ": " + error.message;
}

void raise(const RowError& error, std::initializer_list<FieldName> fields) {
  const std::string message = argument_message(error, fields);
  if (error.invalid_input) throw py::value_error(message);
  throw std::runtime_error(message);
}

double number_argument(const py::handle& value, const std::string& name) {
  const auto refuse = [&] {
    return py::type_error(name + " = " + std::string(py::repr(value)) + ": must be a number (int or float), got " +
                          std::string(py::str(py::type::of(value).attr("__name__"))));
  };
  // Python ints beyond int64 are numbers too; NumPy would make them objects.
  if (PyLong_Check(value.ptr()) && !PyBool_Check(value.ptr())) {
    const double number = PyLong_AsDouble(value.ptr());
    if (number == -1.0 && PyErr_Occurred()) {  // OverflowError: beyond the doubles' 1.8e308
      PyErr_Clear();
      throw py::value_error(name + ": an int too large for a double (magnitude at most 1.8e308)");
    }
    return number;
  }
  const py::array array = py::array::ensure(value);
  if (!array || array.ndim() != 0) throw refuse();
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f') throw refuse();
  return *DoubleArray::ensure(array).data();
}

bool flag_argument(const py::handle& value, const char* name) {
  if (PyBool_Check(value.ptr())) return value.ptr() == Py_True;
  const py::array array = py::array::ensure(value);  // numpy.bool_ too
  if (array && array.ndim() == 0 && array.dtype().kind() == 'b') return PyObject_IsTrue(value.ptr()) == 1;
  throw py::type_error(std::string(name) + " = " + std::string(py::repr(value)) + ": must be True or False");
}

unsigned thread_count(const py::object& threads) {
  if (threads.is_none()) return std::max(1u, std::thread::hardware_concurrency());
  const auto refuse = [&] {
    return py::type_error("threads = " + std::string(py::repr(threads)) + ": must be an int or None");
  };
  if (PyBool_Check(threads.ptr()) || py::isinstance(threads, py::module_::import("numpy").attr("bool_"))) {
    throw refuse();
  }
  // Any integer: int, numpy.int64, whatever implements __index__.
  const auto count = py::reinterpret_steal<py::int_>(PyNumber_Index(threads.ptr()));
  if (!count) {
    PyErr_Clear();
    throw refuse();
  }
  if (count < py::int_(1)) {
    throw py::value_error("threads = " + std::string(py::repr(count)) + ": must be at least 1");
  }
  // A limit, not a demand: more threads than chunks are never started; beyond kMaxThreads the
  // count is capped (2**70 means "as many as useful").
  return count < py::int_(kMaxThreads) ? count.cast<unsigned>() : kMaxThreads;
}

}  // namespace clearjoint::python
