// SPDX-License-Identifier: BSD-3-Clause
// clearjoint.detect on a batch of 100,000 realistic poses, called from Python, against the C++
// loop a program would write over the same poses (detect_contacts into one reused result), in
// one run. Run with --benchmark_repetitions=N --benchmark_enable_random_interleaving=true
// (run_python_bench.py does), and compare per-pose times (items_per_second).
//
// Poses: the realistic family of bench/detection (seed 20170501, 4,096 poses: Table 2 in
// metres, bearings anywhere within 0.2 m, any axis, journals tilted and offset up to 1.5 times
// the room the clearances leave; about half touch), repeated to 100,000.

#include <benchmark/benchmark.h>
#include <pybind11/embed.h>
#include <pybind11/numpy.h>

#include <cstdio>
#include <optional>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "input_families.hpp"

namespace py = pybind11;
namespace geo = clearjoint::geometry;

namespace {

constexpr std::size_t kPoses = 100'000;

struct Batch {
  geo::JointDimensions dimensions;
  std::vector<geo::PartPose> bearings;
  std::vector<geo::PartPose> journals;
};

const Batch& batch() {
  static const Batch b = [] {
    const auto family = clearjoint::bench::generate_family("realistic", clearjoint::bench::SuiteSize::full);
    Batch out;
    out.dimensions = family.front().dimensions;
    for (std::size_t n = 0; n < kPoses; ++n) {
      out.bearings.push_back(family[n % family.size()].bearing);
      out.journals.push_back(family[n % family.size()].journal);
    }
    return out;
  }();
  return b;
}

/// The same poses as NumPy arrays, and clearjoint.detect, in the embedded interpreter.
struct PythonSide {
  py::object detect;
  py::object dimensions;
  py::array_t<double> bearing_center{{py::ssize_t(kPoses), py::ssize_t(3)}};
  py::array_t<double> bearing_axis{{py::ssize_t(kPoses), py::ssize_t(3)}};
  py::array_t<double> journal_center{{py::ssize_t(kPoses), py::ssize_t(3)}};
  py::array_t<double> journal_axis{{py::ssize_t(kPoses), py::ssize_t(3)}};

  PythonSide() {
    py::module_::import("sys").attr("path").attr("insert")(0, CLEARJOINT_PYTHON_PACKAGE_DIR);
    const py::module_ clearjoint = py::module_::import("clearjoint");
    detect = clearjoint.attr("detect");
    const Batch& b = batch();
    using namespace py::literals;
    dimensions = clearjoint.attr("JointDimensions")(
        "bearing_radius"_a = b.dimensions.bearing_radius, "bearing_length"_a = b.dimensions.bearing_length,
        "journal_radius"_a = b.dimensions.journal_radius, "journal_length"_a = b.dimensions.journal_length);
    auto bc = bearing_center.mutable_unchecked<2>(), ba = bearing_axis.mutable_unchecked<2>(),
         jc = journal_center.mutable_unchecked<2>(), ja = journal_axis.mutable_unchecked<2>();
    for (std::size_t n = 0; n < kPoses; ++n) {
      for (int i = 0; i < 3; ++i) {
        bc(n, i) = b.bearings[n].p_WP[i];
        ba(n, i) = b.bearings[n].axis_W[i];
        jc(n, i) = b.journals[n].p_WP[i];
        ja(n, i) = b.journals[n].axis_W[i];
      }
    }
  }
};

std::optional<PythonSide>& python() {
  static std::optional<PythonSide> side;
  return side;
}

void BM_CppLoop(benchmark::State& state) {
  const Batch& b = batch();
  geo::JointContacts out;
  for (auto _ : state) {
    int contacts = 0;
    for (std::size_t n = 0; n < kPoses; ++n) {
      geo::detect_contacts(b.dimensions, b.bearings[n], b.journals[n], out);
      contacts += out.contact_count;
    }
    benchmark::DoNotOptimize(contacts);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPoses));
}

void BM_PythonBatch(benchmark::State& state) {
  PythonSide& p = *python();
  using namespace py::literals;
  const py::int_ threads(state.range(0));
  for (auto _ : state) {
    py::object result = p.detect(p.dimensions, p.bearing_center, p.bearing_axis, p.journal_center,
                                 p.journal_axis, "threads"_a = threads);
    benchmark::DoNotOptimize(result.ptr());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPoses));
}

BENCHMARK(BM_CppLoop)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PythonBatch)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  py::scoped_interpreter interpreter;
  batch();
  python().emplace();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("poses", std::to_string(kPoses) +
                                           " (bench/detection realistic family, seed 20170501, repeated)");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  python().reset();  // release the arrays before the interpreter ends
  return 0;
}
