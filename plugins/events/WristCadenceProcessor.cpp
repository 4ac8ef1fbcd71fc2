#include "plugins/events/WristCadenceProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/events/VectorColumns.h"

#include <cmath>
#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "WristCadenceProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Plan {
    std::shared_ptr<const StreamData> data;
    int acc = -1;
    WristCadenceParams params;
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    auto acc = vectorColumns(c, 0, QStringLiteral("acc_"), QStringLiteral("m/s^2"), QStringLiteral("wrist-cadence"));
    if (!acc) return acc.error();
    plan.acc = *acc;
    WristCadenceParams& p = plan.params;
    p.window = c.number(QStringLiteral("window"));
    p.hop = c.number(QStringLiteral("hop"));
    p.minHarmonicity = c.number(QStringLiteral("min_harmonicity"));
    p.minStd = c.number(QStringLiteral("min_std"));
    p.trackStride = c.number(QStringLiteral("track_stride"));
    p.trackStep = c.number(QStringLiteral("track_step"));
    p.smoothing = c.number(QStringLiteral("smoothing"));
    p.reacquire = c.integer(QStringLiteral("reacquire"));
    if (p.window * p.gridRate > p.fftSize)
        return makeError(QStringLiteral("window: %1 s is %2 samples at %3 Hz, more than the FFT length %4")
                             .arg(p.window)
                             .arg(p.window * p.gridRate)
                             .arg(p.gridRate)
                             .arg(p.fftSize));
    auto input = c.samples(0);
    if (!input) return input.error();
    plan.data = input->data;
    auto interval = input->samplingInterval();
    if (!interval) return interval.error();
    // The norm is averaged onto a 20 Hz grid: the input must sample at least that fast.
    if (*interval > 1.0 / p.gridRate + 1e-9)
        return c.inputError(
            0, QStringLiteral("samples every %1 s; wrist-cadence needs at least %2 Hz").arg(*interval).arg(p.gridRate));
    const auto& t = plan.data->t;
    if (t.back() - t.front() < p.window)
        return c.inputError(
            0,
            QStringLiteral("%1 s of data is shorter than one window (%2 s)").arg(t.back() - t.front()).arg(p.window));
    return plan;
}

}  // namespace

QString WristCadenceProcessor::name() const { return tr("Wrist walking cadence"); }

QString WristCadenceProcessor::description() const {
    return tr(
        "Walking cadence from a wrist-worn accelerometer (Fasel et al. 2017): comb filter on the log "
        "spectrum of 6 s windows of the acceleration norm (harmonics +1, half harmonics -1, stride "
        "frequency 0.4-2 Hz), tracked over time; walking detected from the comb likelihood and the "
        "norm's variability. One row per second.");
}

ParameterSpecs WristCadenceProcessor::parameters() const {
    const WristCadenceParams d;
    using PS = ParameterSpec;
    return {
        PS::number(QStringLiteral("window"), d.window, 2.0, 12.8, QStringLiteral("s"),
                   tr("Window length (thesis eq. 12.1: 6 s, 120 samples at 20 Hz; at most 12.8 s, the FFT of 256).")),
        PS::number(QStringLiteral("hop"), d.hop, 0.05, 60.0, QStringLiteral("s"), tr("Window shift (thesis: 1 s).")),
        PS::number(QStringLiteral("min_harmonicity"), d.minHarmonicity, -kInf, kInf, QString(),
                   tr("Walking needs the harmonics of the comb's stride frequency to exceed their neighbouring "
                      "half harmonics by this much on average (natural log of the amplitude ratio; ours, not in "
                      "the thesis, which segmented walking by hand: see docs/validation/wrist-walking.md).")),
        PS::number(QStringLiteral("min_std"), d.minStd, 0.0, kInf, QStringLiteral("m/s^2"),
                   tr("Walking needs this SD of the acceleration norm in the window (ours: standing is below "
                      "0.1 m/s^2).")),
        PS::number(QStringLiteral("track_stride"), d.trackStride, 0.0, 1.0, QStringLiteral("Hz"),
                   tr("Tracking: a stride frequency further than this from the previous one triggers the search "
                      "in ranges A and B (thesis eq. 12.4: 0.07 Hz).")),
        PS::number(QStringLiteral("track_step"), d.trackStep, 0.0, 2.0, QStringLiteral("Hz"),
                   tr("Tracking: half-width of range B around the previous step frequency (eq. 12.4: 0.14 Hz).")),
        PS::number(QStringLiteral("smoothing"), d.smoothing, 0.0, 0.95, QString(),
                   tr("Weight of the previous cadence in the low-pass c[n] = a c[n-1] + (1-a) c[n] (thesis: "
                      "0.33).")),
        PS::integer(QStringLiteral("reacquire"), d.reacquire, 0, 1000,
                    tr("Windows in a row whose comb maximum lies near neither the tracked stride nor step "
                       "frequency before the track restarts from the maximum (ours, not in the thesis; 1000: "
                       "never).")),
    };
}

QList<InputSpec> WristCadenceProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("Wrist IMU with acc_x..z (m/s^2) sampled at 20 Hz or faster; any orientation.")}};
}

QList<OutputSpec> WristCadenceProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("wrist-cadence"), false, QString(),
                       tr("Per window centre: cadence (steps/min, NaN when not walking), walking (1/0), "
                          "likelihood, norm_max and norm_std (m/s^2).")}};
}

Status WristCadenceProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> WristCadenceProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const StreamData& d = *plan->data;
    context.report(0.1, QStringLiteral("comb filtering"));
    const WristCadence estimator(plan->params);
    const std::vector<CadenceWindow> windows =
        estimator.estimate(d.t.data(), d.values.data() + plan->acc, d.rows(), std::size_t(d.columns));
    if (context.isCancelled()) return cancelledError();
    int walking = 0;
    for (const auto& w : windows) walking += w.walking ? 1 : 0;
    // No walking at all is refused with the likely reasons, not stored as a stream of NaN.
    if (walking == 0)
        return context.inputError(0, QStringLiteral("no walking found in %1 windows (harmonicity below "
                                                    "min_harmonicity = %2 or norm SD below min_std = %3 m/s^2): is "
                                                    "it a wrist IMU during walking?")
                                         .arg(windows.size())
                                         .arg(plan->params.minHarmonicity)
                                         .arg(plan->params.minStd));
    StreamData out(windows.size(), 5);
    for (std::size_t k = 0; k < windows.size(); ++k) {
        const CadenceWindow& w = windows[k];
        out.t[k] = 0.5 * (w.tStart + w.tEnd);
        out.at(k, 0) = w.cadence;
        out.at(k, 1) = w.walking ? 1.0 : 0.0;
        out.at(k, 2) = w.likelihood;
        out.at(k, 3) = w.normMax;
        out.at(k, 4) = w.normStd;
    }
    const QJsonObject attributes{{QStringLiteral("window"), plan->params.window},
                                 {QStringLiteral("hop"), plan->params.hop},
                                 {QStringLiteral("walking_windows"), walking},
                                 {QStringLiteral("time"), QStringLiteral("window centre")}};
    context.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), outputStream(QStringLiteral("wrist-cadence"), QString(),
                                               columnsOf({"cadence", "walking", "likelihood", "norm_max", "norm_std"},
                                                         {"steps/min", "1", "1", "m/s^2", "m/s^2"}),
                                               std::move(out), attributes)});
    return outputs;
}

Expected<std::vector<CadenceWindow>> WristCadenceProcessor::windowsOf(const RunContext& c, int input) {
    auto samples = c.samples(input);
    if (!samples) return samples.error();
    const StreamInfo& info = samples->info();
    const int cadence = info.columnIndex(QStringLiteral("cadence")),
              walking = info.columnIndex(QStringLiteral("walking"));
    const int mx = info.columnIndex(QStringLiteral("norm_max")), sd = info.columnIndex(QStringLiteral("norm_std"));
    if (cadence < 0 || walking < 0 || mx < 0 || sd < 0)
        return c.inputError(input, QStringLiteral("needs the columns cadence, walking, norm_max, norm_std of "
                                                  "wrist-cadence (it has: %1)")
                                       .arg(info.columnNames().join(QStringLiteral(", "))));
    const double window = info.attributes.value(QStringLiteral("window")).toDouble(6.0);
    const StreamData& d = *samples->data;
    std::vector<CadenceWindow> windows(d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k) {
        CadenceWindow& w = windows[k];
        w.tStart = d.t[k] - 0.5 * window;
        w.tEnd = d.t[k] + 0.5 * window;
        w.cadence = d.at(k, cadence);
        w.walking = d.at(k, walking) > 0.5 && std::isfinite(w.cadence);
        w.normMax = d.at(k, mx);
        w.normStd = d.at(k, sd);
    }
    return windows;
}

}  // namespace athlos::events
