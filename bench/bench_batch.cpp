// athlos batch, local engine: 8 projects, each a simulated 10-minute LPS track run (3000 m at 5 m/s,
// ~15 k fixes at ~24 Hz) filtered with position-filter (defaults), with --jobs 1 and --jobs 2. Wall
// time is the figure (the point is using both cores); the counter child_cpu_s is the CPU time of every
// worker process, to tell a loaded machine from an engine that does not scale.
// The projects are built once per run with the athlos executable beside this program (build/bin/).
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>
#include <cstdio>
#include <sys/resource.h>
#include <unistd.h>

namespace {

constexpr int kProjects = 8;

QString athlosExecutable() {
    const QString self = QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath();
    return QFileInfo(self).dir().filePath(QStringLiteral("athlos"));
}

bool run(const QStringList& args, const QString& workDir) {
    QProcess p;
    p.setWorkingDirectory(workDir);
    p.start(athlosExecutable(), args);
    if (!p.waitForFinished(-1) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        std::fprintf(stderr, "athlos %s failed: %s\n", qPrintable(args.join(QLatin1Char(' '))),
                     p.readAllStandardError().constData());
        return false;
    }
    return true;
}

double childCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The base projects and the pipeline, made once.
const QTemporaryDir& fixture() {
    static QTemporaryDir dir;
    static bool made = false;
    if (made) return dir;
    made = true;
    for (int i = 1; i <= kProjects; ++i) {
        const QString p = QStringLiteral("base%1.athlos").arg(i);
        if (!run({QStringLiteral("new"), p}, dir.path()) ||
            !run({QStringLiteral("run"), p, QStringLiteral("simulate-track-run"), QStringLiteral("--output"),
                  QStringLiteral("sim/run"), QStringLiteral("--param"), QStringLiteral("distance=3000"),
                  QStringLiteral("--param"), QStringLiteral("top_speed=5"), QStringLiteral("--param"),
                  QStringLiteral("seed=%1").arg(i)},
                 dir.path()))
            std::abort();
    }
    QFile pipe(dir.filePath(QStringLiteral("pipe.json")));
    if (!pipe.open(QIODevice::WriteOnly) ||
        pipe.write(R"({"name": "filter", "steps": [{"processor": "position-filter", "input": "sim/run",)"
                   R"( "output": "sim/filtered"}]})") <= 0)
        std::abort();
    return dir;
}

void BM_BatchLocal(benchmark::State& state) {
    const QTemporaryDir& dir = fixture();
    const int jobs = int(state.range(0));
    double cpu = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        QStringList args{QStringLiteral("batch"), QStringLiteral("pipe.json")};
        for (int i = 1; i <= kProjects; ++i) {
            const QString copy = QStringLiteral("p%1.athlos").arg(i);
            QFile::remove(dir.filePath(copy));
            QFile::copy(dir.filePath(QStringLiteral("base%1.athlos").arg(i)), dir.filePath(copy));
            args << copy;
        }
        args << QStringLiteral("--jobs") << QString::number(jobs);
        const double before = childCpuSeconds();
        state.ResumeTiming();
        if (!run(args, dir.path())) state.SkipWithError("athlos batch failed");
        cpu += childCpuSeconds() - before;
    }
    state.counters["child_cpu_s"] = benchmark::Counter(cpu, benchmark::Counter::kAvgIterations);
    state.counters["projects"] = kProjects;
}
BENCHMARK(BM_BatchLocal)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
