// SPDX-License-Identifier: MIT
// This machine's memory bandwidth, the roofline's other side (issue 19): STREAM's four kernels
// (McCalpin, "Memory Bandwidth and Machine Balance in Current High Performance Computers", IEEE
// TCCA Newsletter 1995; the definitions of www.cs.virginia.edu/stream/ref.html) on arrays far
// larger than the last-level cache, with 1 and 2 OpenMP threads. Bytes are counted as STREAM
// counts them: copy and scale move 2 x 8 bytes per element, add and triad 3 x 8 (no
// write-allocate traffic). The counter `bytes_per_second` is the figure to compare with the
// bytes a particle-step moves (BENCHMARKS.md, "Roofline (issue 19)"; bench/roofline_count.md).
#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace {

// 3 x 32 Mi doubles = 768 MiB: about 2,000 times a 2-core VM's last-level cache.
constexpr std::size_t kN = std::size_t(32) << 20;

struct Arrays {
  std::vector<double> a, b, c;
  Arrays() : a(kN), b(kN), c(kN) {
    // First touch in parallel, as the kernels will run, so pages sit near their threads.
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < kN; ++i) a[i] = 1.0, b[i] = 2.0, c[i] = 0.0;
  }
};

Arrays& arrays() {
  static Arrays x;
  return x;
}

enum Kernel { Copy, Scale, Add, Triad };

void BM_Stream(benchmark::State& state) {
  const auto kernel = Kernel(state.range(0));
  const int threads = int(state.range(1));
#ifdef _OPENMP
  omp_set_num_threads(threads);
#endif
  Arrays& x = arrays();
  double* a = x.a.data();
  double* b = x.b.data();
  double* c = x.c.data();
  const double s = 3.0;
  for (auto _ : state) {
    switch (kernel) {
      case Copy:
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < kN; ++i) c[i] = a[i];
        break;
      case Scale:
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < kN; ++i) b[i] = s * c[i];
        break;
      case Add:
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < kN; ++i) c[i] = a[i] + b[i];
        break;
      case Triad:
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < kN; ++i) a[i] = b[i] + s * c[i];
        break;
    }
    benchmark::ClobberMemory();
  }
  const double words = kernel == Copy || kernel == Scale ? 2.0 : 3.0;
  state.counters["bytes_per_second"] =
      benchmark::Counter(words * sizeof(double) * double(kN) * double(state.iterations()),
                         benchmark::Counter::kIsRate);
  static const char* names[] = {"copy", "scale", "add", "triad"};
  state.SetLabel(names[kernel]);
}

BENCHMARK(BM_Stream)
    ->ArgNames({"kernel", "threads"})
    ->ArgsProduct({{Copy, Scale, Add, Triad}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
