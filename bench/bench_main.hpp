// The benchmarks' main: Google Benchmark's, after base/keep_freed_memory.hpp's allocator policy,
// so that a benchmark allocates as the CLI does. Use SHAPEVO_BENCHMARK_MAIN() in place of
// BENCHMARK_MAIN().
#pragma once
#include <benchmark/benchmark.h>

#include "base/keep_freed_memory.hpp"

#define SHAPEVO_BENCHMARK_MAIN()                                             \
    int main(int argc, char** argv) {                                        \
        shapevo::keepFreedMemory();                                          \
        benchmark::Initialize(&argc, argv);                                  \
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;    \
        benchmark::RunSpecifiedBenchmarks();                                 \
        benchmark::Shutdown();                                               \
        return 0;                                                            \
    }
