// CSV import throughput on a large IMU file (t + 9 columns, realistic decimals).
//
//   build/bin/bench_csv_import [--benchmark_filter=...]
//   ATHLOS_BENCH_CSV_MB=200 build/bin/bench_csv_import     # file size (default 150 MB)
//
// The file is generated once into a temporary folder. "Import" is importFile() end to end
// (map, parse, units, time check, Stream with its SHA-256 content hash); "Tokenize" is the
// CsvReader number loop alone, the ceiling for the parser; "ContentHash" is the SHA-256 that
// Stream computes over the parsed samples (not the importer's code, but part of every import).
#include "core/io/CsvReader.h"
#include "core/io/Importer.h"

#include <benchmark/benchmark.h>

#include <QFile>
#include <QTemporaryDir>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>

using namespace athlos;

namespace {

struct Fixture {
    QTemporaryDir dir;
    QString path;
    qint64 bytes = 0;
    long long rows = 0;
};

// Writes t at 1 kHz and 9 channels the way sensor exports do: fixed decimals, signs, noise.
const Fixture& fixture() {
    static Fixture f = [] {
        Fixture fx;
        const qint64 target = qint64(qEnvironmentVariableIntValue("ATHLOS_BENCH_CSV_MB") > 0
                                         ? qEnvironmentVariableIntValue("ATHLOS_BENCH_CSV_MB")
                                         : 150)
                              << 20;
        fx.path = fx.dir.filePath("imu_large.csv");
        QFile out(fx.path);
        if (!out.open(QIODevice::WriteOnly)) return fx;
        std::mt19937 rng(7);
        std::normal_distribution<double> noise(0.0, 0.05);
        std::string buffer = "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z\n";
        char line[256];
        for (long long i = 0; fx.bytes + qint64(buffer.size()) < target; ++i) {
            const double t = double(i) * 1e-3;
            const int n = std::snprintf(line, sizeof line, "%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.4f,%.4f\n", t,
                                        std::sin(t) + noise(rng), std::cos(t) + noise(rng), 9.81 + noise(rng),
                                        0.5 * std::sin(2 * t) + noise(rng), -0.2 * std::cos(t) + noise(rng), noise(rng),
                                        20.0 + 5 * std::sin(t), -5.0 + noise(rng), 40.0 - noise(rng));
            buffer.append(line, size_t(n));
            ++fx.rows;
            if (buffer.size() > (4 << 20)) {
                out.write(buffer.data(), qint64(buffer.size()));
                fx.bytes += qint64(buffer.size());
                buffer.clear();
            }
        }
        out.write(buffer.data(), qint64(buffer.size()));
        fx.bytes += qint64(buffer.size());
        return fx;
    }();
    return f;
}

void BM_CsvImportImu(benchmark::State& state) {
    const Fixture& f = fixture();
    ImportOptions options;
    options.format = QStringLiteral("csv");
    options.kind = QStringLiteral("imu");
    options.target = QStringLiteral("bench");
    for (auto _ : state) {
        auto result = importFile(f.path, options);
        if (!result) {
            state.SkipWithError(qPrintable(result.message()));
            return;
        }
        benchmark::DoNotOptimize(result->items.data());
    }
    state.SetBytesProcessed(state.iterations() * f.bytes);
    state.counters["MB"] = double(f.bytes) / 1e6;
    state.counters["rows"] = double(f.rows);
}
BENCHMARK(BM_CsvImportImu)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void BM_CsvTokenizeNumbers(benchmark::State& state) {
    const Fixture& f = fixture();
    MappedFile mapped;
    if (Status s = mapped.open(f.path); !s) {
        state.SkipWithError(qPrintable(s.message()));
        return;
    }
    for (auto _ : state) {
        CsvReader reader(mapped.begin(), mapped.end());
        QStringList header;
        reader.readHeader(header);
        double sum = 0.0;
        while (reader.nextRecord()) {
            double v;
            for (int c = 0; c < header.size(); ++c)
                if (reader.number(v) == CsvReader::Field::Number) sum += v;
            reader.finishRecord();
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetBytesProcessed(state.iterations() * f.bytes);
}
BENCHMARK(BM_CsvTokenizeNumbers)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

// The SHA-256 content hash every new Stream computes (StreamData::contentHash), on the samples of the
// same file: the part of "Import" that is not parsing.
void BM_ContentHashOfImport(benchmark::State& state) {
    const Fixture& f = fixture();
    ImportOptions options;
    options.format = QStringLiteral("csv");
    options.kind = QStringLiteral("imu");
    options.target = QStringLiteral("bench");
    auto result = importFile(f.path, options);
    if (!result) {
        state.SkipWithError(qPrintable(result.message()));
        return;
    }
    const StreamData& data = **std::get<Stream>(result->items.front().item).data();
    for (auto _ : state) benchmark::DoNotOptimize(data.contentHash());
    state.SetBytesProcessed(state.iterations() * f.bytes);  // per CSV byte, comparable with the others
}
BENCHMARK(BM_ContentHashOfImport)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();
