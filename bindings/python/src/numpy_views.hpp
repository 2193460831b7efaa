// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// NumPy inputs read as rows of 3-vectors or of scalars, with NumPy's broadcasting of a single row
// over a batch, and the error messages that name the argument and the row.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <exception>
#include <initializer_list>
#include <new>
#include <string>

#include "clearjoint/geometry/arithmetic/vector3.hpp"
#include "clearjoint/validation_error.hpp"

namespace clearjoint::python {

/// What VectorRows and ScalarRows share: an argument held as a C-contiguous float64 array
/// (converted from lists and integer or floating dtypes on the way in; bools, complex numbers,
/// datetimes, strings, None and masked values refused) that is either one row, broadcast over
/// every row of a batch, or N rows.
class BroadcastRows {
 public:
  bool batched() const { return batched_; }
  std::size_t rows() const { return rows_; }
  const char* name() const { return name_; }

 protected:
  /// `row_width` 3: shape (3,) or (N, 3); `row_width` 1: shape () or (N,). Throws TypeError (not
  /// numbers) or ValueError (another shape) naming `name`.
  BroadcastRows(const pybind11::handle& value, const char* name, std::size_t row_width);
  /// The first of the `row_width` numbers of `row` (of the one row when not batched).
  const double* row_data(std::size_t row) const { return data_ + (batched_ ? row_width_ * row : 0); }

 private:
  pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast> array_;
  const double* data_ = nullptr;
  std::size_t row_width_;
  std::size_t rows_ = 1;
  bool batched_ = false;
  const char* name_;
};

/// An argument of shape (3,) (one vector, broadcast over every row) or (N, 3) (one per row).
class VectorRows : public BroadcastRows {
 public:
  VectorRows(const pybind11::handle& value, const char* name) : BroadcastRows(value, name, 3) {}
  geometry::Vector3 operator[](std::size_t row) const {
    const double* p = row_data(row);
    return {p[0], p[1], p[2]};
  }
};

/// An argument of shape () (one number, broadcast) or (N,).
class ScalarRows : public BroadcastRows {
 public:
  ScalarRows(const pybind11::handle& value, const char* name) : BroadcastRows(value, name, 1) {}
  double operator[](std::size_t row) const { return *row_data(row); }
};

/// What a list of arguments broadcasts to: `rows` (N) and whether any argument is batched (a
/// batch of one differs from a single query: it returns arrays). Throws ValueError when two
/// batched arguments have different lengths, naming both.
struct Broadcast {
  std::size_t rows = 1;
  bool batched = false;
};
template <typename... Inputs>
Broadcast broadcast(const Inputs&... inputs);

void throw_length_mismatch(const char* first, std::size_t first_rows, const char* second,
                           std::size_t second_rows);

template <typename... Inputs>
Broadcast broadcast(const Inputs&... inputs) {
  Broadcast result;
  const char* batched_name = nullptr;
  auto visit = [&](const auto& input) {
    if (!input.batched()) return;
    if (batched_name != nullptr && input.rows() != result.rows) {
      throw_length_mismatch(batched_name, result.rows, input.name(), input.rows());
    }
    batched_name = input.name();
    result.rows = input.rows();
    result.batched = true;
  };
  (visit(inputs), ...);
  return result;
}

/// A row a batch could not answer, thrown by a worker: its row, the library's message and, for
/// bad input (a ValidationError, raised as ValueError), the path of the field at fault.
struct RowError {
  std::size_t row = 0;
  std::string message;
  std::string field_path;
  bool invalid_input = false;

  static RowError invalid(std::size_t row, const ValidationError& e) {
    return {row, e.what(), std::string(e.field_path()), true};
  }
  static RowError failed(std::size_t row, const std::exception& e) { return {row, e.what(), "", false}; }
};

/// Runs `query` for row n, turning what it throws into a RowError; bad_alloc passes through
/// (MemoryError, not a bad row).
template <class Query>
void answer_row(std::size_t n, Query&& query) {
  try {
    query();
  } catch (const ValidationError& e) {
    throw RowError::invalid(n, e);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw RowError::failed(n, e);
  }
}

/// Turn a library message about a field into one about the Python argument and its row: the
/// field "bearing.axis_W" of "bearing.axis_W = [0, 0, 0]: must not be ..." is, with
/// {"bearing.axis_W", bearing_axis}, "bearing_axis[7] = [0, 0, 0]: must not be ..." (no index
/// for a broadcast argument); any other message gets "row 7: " before it.
struct FieldName {
  const char* library;  ///< the library's field path, "bearing.axis_W"
  const char* argument; ///< the Python argument, "bearing_axis"
  bool batched;
};
std::string argument_message(const RowError& error, std::initializer_list<FieldName> fields);

/// ValueError (bad input) or RuntimeError with argument_message's text.
[[noreturn]] void raise(const RowError& error, std::initializer_list<FieldName> fields);

/// Run `batch()` (with the GIL held); when it runs out of memory (std::bad_alloc from the
/// library or a worker, MemoryError from NumPy), raise MemoryError naming the call and the
/// batch's size, "detect: a batch of 2000000 poses does not fit in the memory available ...",
/// instead of a bare "std::bad_alloc".
template <class Batch>
auto within_memory(const char* call, std::size_t rows, const char* row_name, Batch&& batch) {
  const auto refuse = [&]() -> pybind11::error_already_set {
    PyErr_Format(PyExc_MemoryError,
                 "%s: a batch of %zu %s does not fit in the memory available for its results; "
                 "pass fewer at a time",
                 call, rows, row_name);
    return pybind11::error_already_set();
  };
  try {
    return batch();
  } catch (const std::bad_alloc&) {
    throw refuse();
  } catch (pybind11::error_already_set& e) {
    if (!e.matches(PyExc_MemoryError)) throw;
    throw refuse();
  }
}

/// A number given as a scalar: a Python int or float or a NumPy integer or floating scalar;
/// TypeError naming `name` for anything else (bools, None, strings, complex), ValueError naming it
/// for an int beyond the doubles' range.
double number_argument(const pybind11::handle& value, const std::string& name);

/// A switch: True or False (numpy.bool_ too); TypeError naming `name` for anything else (None, 2).
bool flag_argument(const pybind11::handle& value, const char* name);

/// Threads to use: None -> every core the machine reports; else any positive integer (int,
/// numpy.int64, ...), capped at kMaxThreads. TypeError for non-integers and bools, ValueError
/// "threads = 0: must be at least 1".
inline constexpr unsigned kMaxThreads = 1024;
unsigned thread_count(const pybind11::object& threads);

}  // namespace clearjoint::python
