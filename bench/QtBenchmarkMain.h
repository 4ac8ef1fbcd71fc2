#pragma once
// main() for benchmarks that paint widgets: a QApplication on the offscreen platform (unless the
// caller chose one) around Google Benchmark's usual run.
#include <QApplication>
#include <benchmark/benchmark.h>

#define ATHLOS_QT_BENCHMARK_MAIN()                                                                   \
    int main(int argc, char** argv) {                                                                \
        /* Before QApplication: the platform plugin is chosen in its constructor. */                 \
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen"); \
        QApplication app(argc, argv);                                                                \
        benchmark::Initialize(&argc, argv);                                                          \
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;                            \
        benchmark::RunSpecifiedBenchmarks();                                                         \
        benchmark::Shutdown();                                                                       \
        return 0;                                                                                    \
    }
