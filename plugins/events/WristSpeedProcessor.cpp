#include "plugins/events/WristSpeedProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/events/WristCadenceProcessor.h"
#include "plugins/events/WristSpeedModel.h"

#include <QJsonArray>
#include <cmath>
#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "WristSpeedProcessor"};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const QStringList kFeatureColumns{QStringLiteral("max_x_std"), QStringLiteral("cadence"),
                                  QStringLiteral("pressure_change"), QStringLiteral("height")};
const QStringList kFeatureUnits{QStringLiteral("m^2/s^4"), QStringLiteral("steps/min"), QStringLiteral("Pa"),
                                QStringLiteral("m")};

// The walking windows with their features (cadence input 0, barometer input 1).
struct Features {
    std::vector<CadenceWindow> windows;
    std::vector<WristFeatures> x;
    std::vector<std::size_t> rows;  // window index of each x
};

Expected<Features> featuresOf(const RunContext& c, double height) {
    Features f;
    auto windows = WristCadenceProcessor::windowsOf(c, 0);
    if (!windows) return windows.error();
    f.windows = std::move(*windows);
    auto baro = c.samples(1);
    if (!baro) return baro.error();
    const int p = baro->info().columnIndex(QStringLiteral("pressure"));
    if (p < 0) return c.inputError(1, QStringLiteral("has no column 'pressure'"));
    const QString unit = baro->info().columns[std::size_t(p)].unit;
    if (unit != QLatin1String("Pa"))
        return c.inputError(
            1, QStringLiteral("column pressure is in '%1'; expected Pa (import it as kind barometer)").arg(unit));
    const StreamData& d = *baro->data;
    f.x = wristSpeedFeatureRows(f.windows, d.t, d.values.data() + p, std::size_t(d.columns), height, f.rows);
    if (f.x.empty())
        return c.inputError(0, QStringLiteral("no walking window with barometer samples 9.5 s before its end "
                                              "(barometer covers %1 to %2 s)")
                                   .arg(d.rows() ? d.t.front() : 0.0)
                                   .arg(d.rows() ? d.t.back() : 0.0));
    return f;
}

Expected<WristSpeedModel> modelOf(const RunContext& c, int input) {
    auto table = c.requireTable(input);
    if (!table) return table.error();
    QString error;
    WristSpeedModel m =
        WristSpeedModel::fromJson((*table)->attributes.value(QStringLiteral("model")).toObject(), &error);
    if (!m.valid()) return c.inputError(input, QStringLiteral("not a wrist-speed model: %1").arg(error));
    return m;
}

ParameterSpec heightParameter() {
    return ParameterSpec::number(QStringLiteral("height"), 0.0, 0.0, 2.5, QStringLiteral("m"),
                                 tr("The walker's height (feature x4 of eq. 12.6); required, 0 = not given."));
}

Status checkHeight(const RunContext& c) {
    const double h = c.number(QStringLiteral("height"));
    if (h < 1.0) return makeError(QStringLiteral("height: give the walker's height in m (1.0 to 2.5), got %1").arg(h));
    return {};
}

}  // namespace

// ---- wrist-speed-train ----

QString WristSpeedTrainProcessor::name() const { return tr("Train wrist walking speed"); }

QString WristSpeedTrainProcessor::description() const {
    return tr(
        "Trains the wrist walking-speed model (Fasel et al. 2017): features max*std of the acceleration norm, "
        "cadence, barometric pressure change over 9 s and height per walking window; 16 k-means clusters, "
        "each with its own linear model fitted to a reference speed. Give an earlier model to add this "
        "walker's windows to its training rows.");
}

ParameterSpecs WristSpeedTrainProcessor::parameters() const {
    const WristSpeedModelParams d;
    return {heightParameter(),
            ParameterSpec::integer(QStringLiteral("clusters"), d.clusters, 1, 256,
                                   tr("k-means clusters, each with a linear model (thesis: 16).")),
            ParameterSpec::integer(QStringLiteral("min_cluster_rows"), d.minClusterRows, 6, 100000,
                                   tr("A cluster with fewer training windows uses the global linear model.")),
            ParameterSpec::integer(QStringLiteral("seed"), int(d.seed), 0, std::numeric_limits<int>::max(),
                                   tr("Seed of the k-means++ initialisation (deterministic training).")),
            ParameterSpec::number(QStringLiteral("min_speed"), 0.2, 0.0, 10.0, QStringLiteral("m/s"),
                                  tr("Windows whose mean reference speed is below this are not used."))};
}

QList<InputSpec> WristSpeedTrainProcessor::inputs() const {
    return {
        InputSpec{
            QStringLiteral("cadence"), {QStringLiteral("wrist-cadence")}, false, false, tr("Output of wrist-cadence.")},
        InputSpec{QStringLiteral("barometer"),
                  {QStringLiteral("barometer")},
                  false,
                  false,
                  tr("Barometric pressure (Pa) of the same wrist sensor.")},
        InputSpec{QStringLiteral("reference"),
                  {},
                  false,
                  false,
                  tr("Reference walking speed: a stream with a column 'speed' (m/s), e.g. from GNSS.")},
        InputSpec{QStringLiteral("previous"),
                  {QStringLiteral("wrist-speed-model")},
                  true,
                  true,
                  tr("An earlier model whose training windows are kept.")}};
}

QList<OutputSpec> WristSpeedTrainProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("wrist-speed-model"), true, QString(),
                       tr("Training windows (t, max_x_std, cadence, pressure_change, height, speed) with the model "
                          "in the attributes.")}};
}

Status WristSpeedTrainProcessor::prepare(const RunContext& c) const {
    if (auto s = checkHeight(c); !s.ok()) return s;
    auto ref = c.samples(2);
    if (!ref) return ref.error();
    const int col = ref->info().columnIndex(QStringLiteral("speed"));
    if (col < 0) return c.inputError(2, QStringLiteral("has no column 'speed' (the reference speed in m/s)"));
    const QString unit = ref->info().columns[std::size_t(col)].unit;
    if (!unit.isEmpty() && unit != QLatin1String("m/s"))
        return c.inputError(2, QStringLiteral("column speed is in '%1'; expected m/s").arg(unit));
    return {};
}

Expected<std::vector<ProcessorOutput>> WristSpeedTrainProcessor::run(const RunContext& c) const {
    if (auto s = prepare(c); !s.ok()) return s.error();
    const double height = c.number(QStringLiteral("height"));
    auto features = featuresOf(c, height);
    if (!features) return features.error();
    auto ref = c.samples(2);
    if (!ref) return ref.error();
    const StreamData& r = *ref->data;
    const int speedCol = ref->info().columnIndex(QStringLiteral("speed"));
    const double minSpeed = c.number(QStringLiteral("min_speed"));

    // Rows: the earlier model's, then this recording's windows with their mean reference speed.
    std::vector<std::vector<double>> columns(6);  // t, 4 features, speed
    if (c.table(3)) {
        const Table& previous = *c.table(3);
        QStringList names{QStringLiteral("t")};
        names << kFeatureColumns << QStringLiteral("speed");
        for (int k = 0; k < names.size(); ++k) {
            const TableColumn* col = previous.column(names[k]);
            if (!col || col->isText)
                return c.inputError(3,
                                    QStringLiteral("has no numeric column '%1' of a wrist-speed model").arg(names[k]));
            columns[std::size_t(k)] = col->numbers;
        }
    }
    int added = 0;
    for (std::size_t i = 0; i < features->x.size(); ++i) {
        const CadenceWindow& w = features->windows[features->rows[i]];
        double sum = 0.0;
        int n = 0;
        for (auto it = std::lower_bound(r.t.begin(), r.t.end(), w.tStart); it != r.t.end() && *it < w.tEnd; ++it) {
            const double v = r.at(std::size_t(it - r.t.begin()), speedCol);
            if (std::isfinite(v)) {
                sum += v;
                ++n;
            }
        }
        if (n == 0 || sum / n < minSpeed) continue;
        columns[0].push_back(0.5 * (w.tStart + w.tEnd));
        for (int k = 0; k < kWristSpeedFeatures; ++k)
            columns[std::size_t(k) + 1].push_back(features->x[i][std::size_t(k)]);
        columns[5].push_back(sum / n);
        ++added;
    }
    if (added == 0)
        return c.inputError(
            2, QStringLiteral("no walking window has a reference speed of at least min_speed = %1 m/s").arg(minSpeed));
    if (c.isCancelled()) return cancelledError();
    c.report(0.5, QStringLiteral("clustering"));
    std::vector<WristFeatures> x(columns[0].size());
    for (std::size_t k = 0; k < x.size(); ++k)
        for (int i = 0; i < kWristSpeedFeatures; ++i) x[k][std::size_t(i)] = columns[std::size_t(i) + 1][k];
    WristSpeedModelParams params;
    params.clusters = c.integer(QStringLiteral("clusters"));
    params.minClusterRows = c.integer(QStringLiteral("min_cluster_rows"));
    params.seed = unsigned(c.integer(QStringLiteral("seed")));
    QString error;
    const WristSpeedModel model = WristSpeedModel::train(x, columns[5], params, &error);
    if (!model.valid()) return makeError(QStringLiteral("clusters: %1").arg(error));

    Table table;
    table.kind = QStringLiteral("wrist-speed-model");
    const QStringList names = QStringList{QStringLiteral("t")} + kFeatureColumns + QStringList{QStringLiteral("speed")};
    const QStringList units = QStringList{QStringLiteral("s")} + kFeatureUnits + QStringList{QStringLiteral("m/s")};
    for (int k = 0; k < names.size(); ++k)
        table.columns.push_back(TableColumn{names[k], units[k], false, std::move(columns[std::size_t(k)]), {}});
    const int previousRows = c.table(3) ? int(c.table(3)->rows()) : 0;
    table.attributes = QJsonObject{{QStringLiteral("model"), model.toJson()},
                                   {QStringLiteral("rows_from_previous"), previousRows},
                                   {QStringLiteral("rows_added"), added}};
    c.report(1.0);
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), std::move(table)});
    return out;
}

// ---- wrist-speed ----

QString WristSpeedProcessor::name() const { return tr("Wrist walking speed"); }

QString WristSpeedProcessor::description() const {
    return tr(
        "Walking speed per cadence window from a trained wrist-speed model (Fasel et al. 2017): the nearest of "
        "the k-means centroids picks the linear model of the features max*std of the acceleration norm, "
        "cadence, barometric pressure change over 9 s and height.");
}

ParameterSpecs WristSpeedProcessor::parameters() const { return {heightParameter()}; }

QList<InputSpec> WristSpeedProcessor::inputs() const {
    return {
        InputSpec{
            QStringLiteral("cadence"), {QStringLiteral("wrist-cadence")}, false, false, tr("Output of wrist-cadence.")},
        InputSpec{QStringLiteral("barometer"),
                  {QStringLiteral("barometer")},
                  false,
                  false,
                  tr("Barometric pressure (Pa) of the same wrist sensor.")},
        InputSpec{QStringLiteral("model"),
                  {QStringLiteral("wrist-speed-model")},
                  true,
                  false,
                  tr("A model from wrist-speed-train.")}};
}

QList<OutputSpec> WristSpeedProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("wrist-speed"), false, QString(),
                       tr("speed (m/s, NaN when not walking) and the cluster used, per cadence window.")}};
}

Status WristSpeedProcessor::prepare(const RunContext& c) const {
    if (auto s = checkHeight(c); !s.ok()) return s;
    return statusOf(modelOf(c, 2));
}

Expected<std::vector<ProcessorOutput>> WristSpeedProcessor::run(const RunContext& c) const {
    if (auto s = checkHeight(c); !s.ok()) return s.error();
    auto model = modelOf(c, 2);
    if (!model) return model.error();
    auto features = featuresOf(c, c.number(QStringLiteral("height")));
    if (!features) return features.error();
    StreamData out(features->windows.size(), 2);
    for (std::size_t k = 0; k < out.rows(); ++k) {
        const CadenceWindow& w = features->windows[k];
        out.t[k] = 0.5 * (w.tStart + w.tEnd);
        out.at(k, 0) = kNaN;
        out.at(k, 1) = kNaN;
    }
    int negative = 0;
    for (std::size_t i = 0; i < features->x.size(); ++i) {
        const std::size_t k = features->rows[i];
        const double v = model->predict(features->x[i]);
        // A linear model far outside its cluster can go below zero: that is not a walking speed.
        if (!(v > 0.0)) {
            ++negative;
            continue;
        }
        out.at(k, 0) = v;
        out.at(k, 1) = model->cluster(features->x[i]);
    }
    c.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), outputStream(QStringLiteral("wrist-speed"), QString(),
                                               columnsOf({"speed", "cluster"}, {"m/s", "1"}), std::move(out),
                                               QJsonObject{{QStringLiteral("walking_windows"), int(features->x.size())},
                                                           {QStringLiteral("rejected_non_positive"), negative}})});
    return outputs;
}

}  // namespace athlos::events
