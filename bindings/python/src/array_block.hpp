// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Several NumPy result arrays carved out of one allocation.
//
// Why: a batch returns about fifteen arrays of 0.1 to 4 MB. Allocated one by one, glibc's malloc
// gives each back to the system when Python frees it and faults fresh pages in on the next call
// (perf: page faults and heap trimming were a sixth of a batch's time); one block of the total
// size is kept and reused by malloc from call to call. The arrays are views into the block, which
// lives as long as any of them.

#include <pybind11/numpy.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace clearjoint::python {

class ArrayBlock {
 public:
  /// Plan an array of `shape`; returns the handle for data() and array().
  template <typename T>
  std::size_t plan(std::vector<pybind11::ssize_t> shape) {
    std::size_t bytes = sizeof(T);
    for (pybind11::ssize_t extent : shape) bytes *= static_cast<std::size_t>(extent);
    constexpr std::size_t kAlignment = 64;  // a cache line: every array starts on its own
    const std::size_t offset = (total_ + kAlignment - 1) / kAlignment * kAlignment;
    plans_.push_back({std::move(shape), offset});
    total_ = offset + bytes;
    return plans_.size() - 1;
  }

  /// Allocate the block (with the GIL held), after every plan().
  void allocate() {
    block_ = pybind11::array_t<std::uint8_t>(static_cast<pybind11::ssize_t>(total_ + 1));
    base_ = block_.mutable_data();
  }

  template <typename T>
  T* data(std::size_t handle) const {
    return reinterpret_cast<T*>(base_ + plans_[handle].offset);
  }

  /// The planned array as a view into the block (with the GIL held).
  template <typename T>
  pybind11::array_t<T> array(std::size_t handle) const {
    return pybind11::array_t<T>(plans_[handle].shape, data<T>(handle), block_);
  }

 private:
  struct Plan {
    std::vector<pybind11::ssize_t> shape;
    std::size_t offset;
  };
  std::vector<Plan> plans_;
  std::size_t total_ = 0;
  pybind11::array_t<std::uint8_t> block_;
  std::uint8_t* base_ = nullptr;
};

}  // namespace clearjoint::python
