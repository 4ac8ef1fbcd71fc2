// The resample and butterworth processors through the real runner (and the real plugin), on a small
// in-memory project: parameters as the CLI passes them, outputs, provenance, errors, cancellation.
#include "plugins/signal/ButterworthProcessor.h"
#include "plugins/signal/ResampleProcessor.h"

#include "core/processing/ProcessorPlugin.h"
#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QJsonArray>
#include <QPluginLoader>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

using namespace athlos;
using athlos::signal::ButterworthProcessor;
using athlos::signal::ResampleProcessor;

namespace {

constexpr double kPi = std::numbers::pi;

// acc_x = ramp + sines, a unit quaternion rotating about z, and a movement flag.
Stream makeImuStream(const std::vector<double>& t) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.frame = QStringLiteral("sensor");
    info.columns = {{"acc_x", "m/s^2"}, {"qw", "1"}, {"qx", "1"}, {"qy", "1"}, {"qz", "1"}, {"movement", "1"}};
    info.attributes.insert(QStringLiteral("device"), QStringLiteral("test"));
    StreamData data(t.size(), 6);
    data.t = t;
    for (std::size_t i = 0; i < t.size(); ++i) {
        data.at(i, 0) = std::sin(2 * kPi * 1.0 * t[i]) + 0.5 * std::sin(2 * kPi * 40.0 * t[i]);
        data.at(i, 1) = std::cos(0.25 * t[i]);
        data.at(i, 2) = data.at(i, 3) = 0.0;
        data.at(i, 4) = std::sin(0.25 * t[i]);
        data.at(i, 5) = t[i] > 2.0 ? 1.0 : 0.0;
    }
    return Stream(std::move(info), std::move(data));
}

std::vector<double> uniformTimes(int n, double fs) {
    std::vector<double> t(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) t[i] = i / fs;
    return t;
}

class SignalProcessors : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("test.athlos")));
        project_->putStream(QStringLiteral("run1/imu"), makeImuStream(uniformTimes(1000, 200.0)));
        std::vector<double> jittered = uniformTimes(1000, 200.0);
        for (std::size_t i = 0; i < jittered.size(); ++i) jittered[i] += (i % 2 ? 1e-3 : 0.0);  // 20 % jitter
        project_->putStream(QStringLiteral("run1/raw"), makeImuStream(jittered));
    }

    Expected<RunOutcome> run(const Processor& processor, const QString& input, const QVariantMap& params,
                             const Progress& progress = {}) {
        return runProcessor(*project_, processor, {processor.id(), {input}, QStringLiteral("run1/out"), params},
                            progress);
    }

    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
};

QVariantMap params(std::initializer_list<std::pair<const char*, const char*>> items) {
    QVariantMap map;
    for (auto [k, v] : items) map.insert(QString::fromLatin1(k), QString::fromLatin1(v));  // strings, as from the CLI
    return map;
}

}  // namespace

TEST_F(SignalProcessors, ResampleKeepsKindFrameColumnsAndRecordsRate) {
    const ResampleProcessor resample;
    auto outcome = run(resample, QStringLiteral("run1/raw"), params({{"rate", "50"}, {"max_gap", "0.1"}}));
    ASSERT_TRUE(outcome.ok()) << outcome.message().toStdString();
    EXPECT_EQ(outcome->written, QStringList{QStringLiteral("run1/out")});
    const Stream* out = project_->stream(QStringLiteral("run1/out"));
    const Stream* in = project_->stream(QStringLiteral("run1/raw"));
    ASSERT_TRUE(out);
    EXPECT_EQ(out->kind(), QStringLiteral("imu"));
    EXPECT_EQ(out->info().frame, QStringLiteral("sensor"));
    EXPECT_EQ(out->info().columns, in->info().columns);
    EXPECT_EQ(out->info().attributes.value(QStringLiteral("sampling_rate")).toDouble(), 50.0);
    EXPECT_EQ(out->info().attributes.value(QStringLiteral("device")).toString(), QStringLiteral("test"));
    EXPECT_EQ(out->info().provenance.processorId, QStringLiteral("resample"));
    const auto data = *out->data();
    const auto source = *in->data();
    EXPECT_NEAR(data->medianInterval(), 0.02, 1e-12);
    for (std::size_t k = 0; k < data->rows(); ++k) {
        EXPECT_NEAR(data->t[k], source->t.front() + k * 0.02, 1e-12);
        const double norm = std::hypot(data->at(k, 1), data->at(k, 4));
        EXPECT_NEAR(norm, 1.0, 1e-12);
        EXPECT_NEAR(std::atan2(data->at(k, 4), data->at(k, 1)), 0.25 * data->t[k], 1e-9);  // SLERP angle
        EXPECT_TRUE(data->at(k, 5) == 0.0 || data->at(k, 5) == 1.0);
    }
}

TEST_F(SignalProcessors, ResampleErrorsNameTheParameterOrStream) {
    const ResampleProcessor resample;
    auto zero = run(resample, QStringLiteral("run1/imu"), params({{"rate", "0"}}));
    ASSERT_FALSE(zero.ok());
    EXPECT_TRUE(zero.message().startsWith(QLatin1String("resample: rate must be"))) << zero.message().toStdString();
    auto missing = run(resample, QStringLiteral("run1/imu"), params({}));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(missing.message().contains(QLatin1String("'rate' is required"))) << missing.message().toStdString();
    project_->putStream(QStringLiteral("run1/single"), makeImuStream({0.5}));
    auto single = run(resample, QStringLiteral("run1/single"), params({{"rate", "10"}}));
    ASSERT_FALSE(single.ok());
    EXPECT_TRUE(single.message().contains(QLatin1String("run1/single")) &&
                single.message().contains(QLatin1String("at least 2")))
        << single.message().toStdString();
}

TEST_F(SignalProcessors, ButterworthRemovesHighFrequencyAndLeavesQuaternionsAlone) {
    const ButterworthProcessor butterworth;
    QVariantMap p = params({{"cutoff", "10"}});
    std::vector<double> fractions;
    const Progress progress([&](double f, const QString&) { fractions.push_back(f); });
    auto outcome = run(butterworth, QStringLiteral("run1/imu"), p, progress);
    ASSERT_TRUE(outcome.ok()) << outcome.message().toStdString();
    EXPECT_EQ(outcome->parameters.value(QStringLiteral("zero_phase")).toBool(), true);
    EXPECT_EQ(outcome->parameters.value(QStringLiteral("order")).toInt(), 2);
    const auto out = *project_->stream(QStringLiteral("run1/out"))->data();
    const auto in = *project_->stream(QStringLiteral("run1/imu"))->data();
    // Zero-phase order 2 at 10 Hz: the 1 Hz component passes with gain |H(1)|² ≈ 1, 40 Hz is gone.
    for (std::size_t i = 100; i < 900; ++i) EXPECT_NEAR(out->at(i, 0), std::sin(2 * kPi * in->t[i]), 2e-3);
    for (int c = 1; c < 6; ++c)
        for (std::size_t i = 0; i < in->rows(); ++i) EXPECT_EQ(out->at(i, c), in->at(i, c));
    ASSERT_FALSE(fractions.empty());
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

TEST_F(SignalProcessors, ButterworthErrorsNameTheParameter) {
    const ButterworthProcessor butterworth;
    auto message = [&](const QString& input, const QVariantMap& p) {
        auto outcome = run(butterworth, input, p);
        EXPECT_FALSE(outcome.ok());
        return outcome.ok() ? QString() : outcome.message();
    };
    const QString imu = QStringLiteral("run1/imu");
    const QString nyquist = message(imu, params({{"cutoff", "100"}}));
    EXPECT_TRUE(nyquist.contains(QLatin1String("cutoff")) &&
                nyquist.contains(QLatin1String("Nyquist frequency 100 Hz")))
        << nyquist.toStdString();
    const QString jitter = message(QStringLiteral("run1/raw"), params({{"cutoff", "10"}}));
    EXPECT_TRUE(jitter.contains(QLatin1String("not uniformly sampled")) && jitter.contains(QLatin1String("resample")))
        << jitter.toStdString();
    EXPECT_TRUE(
        message(imu, params({{"cutoff", "10"}, {"columns", "acc_x,qw"}})).contains(QLatin1String("quaternion")));
    EXPECT_TRUE(message(imu, params({{"cutoff", "10"}, {"columns", "movement"}})).contains(QLatin1String("flag")));
    EXPECT_TRUE(
        message(imu, params({{"cutoff", "10"}, {"columns", "gyr_x"}})).contains(QLatin1String("no column 'gyr_x'")));
    EXPECT_TRUE(message(imu, params({{"cutoff", "10"}, {"type", "bandpass"}})).contains(QLatin1String("cutoff_high")));
    EXPECT_TRUE(message(imu, params({{"cutoff", "10"}, {"cutoff_high", "20"}})).contains(QLatin1String("cutoff_high")));
    EXPECT_TRUE(message(imu, params({})).contains(QLatin1String("cutoff")));

    project_->putStream(QStringLiteral("run1/short"), makeImuStream(uniformTimes(12, 200.0)));
    const QString tooShort = message(QStringLiteral("run1/short"), params({{"cutoff", "10"}, {"order", "4"}}));
    EXPECT_TRUE(tooShort.contains(QLatin1String("at least 16 rows"))) << tooShort.toStdString();
    EXPECT_TRUE(
        run(butterworth, QStringLiteral("run1/short"), params({{"cutoff", "10"}, {"zero_phase", "false"}})).ok());
    EXPECT_FALSE(project_->stream(QStringLiteral("run1/out")) == nullptr);
}

TEST_F(SignalProcessors, CancellationLeavesProjectUnchanged) {
    CancelToken token;
    token.cancel();
    const Progress cancelled([](double, const QString&) {}, token);
    const ResampleProcessor resample;
    const ButterworthProcessor butterworth;
    for (auto [processor, p] : {std::pair<const Processor*, QVariantMap>{&resample, params({{"rate", "100"}})},
                                {&butterworth, params({{"cutoff", "10"}})}}) {
        auto outcome = run(*processor, QStringLiteral("run1/imu"), p, cancelled);
        ASSERT_FALSE(outcome.ok());
        EXPECT_EQ(outcome.message(), cancelledError().message);
        EXPECT_EQ(project_->stream(QStringLiteral("run1/out")), nullptr);
    }
}

TEST_F(SignalProcessors, PluginIsDiscoveredAndRunsFromTheRegistry) {
    const QString file =
        QDir(QStringLiteral(ATHLOS_BUILD_PLUGIN_DIR)).absoluteFilePath(QStringLiteral("athlos_plugin_signal.so"));
    QPluginLoader loader(file);
    const QJsonObject meta = loader.metaData().value(QStringLiteral("MetaData")).toObject();
    EXPECT_EQ(meta.value(QStringLiteral("family")).toString(), QStringLiteral("signal"));
    EXPECT_EQ(meta.value(QStringLiteral("processors")).toArray().size(), 2);

    ProcessorRegistry registry;
    registry.loadFrom({QStringLiteral(ATHLOS_BUILD_PLUGIN_DIR)});
    const auto resample = registry.find(QStringLiteral("resample"));
    const auto butterworth = registry.find(QStringLiteral("butterworth"));
    ASSERT_TRUE(resample && butterworth) << registry.loadErrors().join(QLatin1Char('\n')).toStdString();

    const QJsonObject schema = resample->describe();
    bool rateRequired = false;
    for (const auto& p : schema.value(QStringLiteral("parameters")).toArray())
        if (p.toObject().value(QStringLiteral("name")) == QStringLiteral("rate"))
            rateRequired = p.toObject().value(QStringLiteral("required")).toBool();
    EXPECT_TRUE(rateRequired);

    // resample → butterworth, the pipeline a user runs on jittered data.
    ASSERT_TRUE(run(*resample, QStringLiteral("run1/raw"), params({{"rate", "200"}})).ok());
    auto filtered = runProcessor(*project_, *butterworth,
                                 {QStringLiteral("butterworth"),
                                  {QStringLiteral("run1/out")},
                                  QStringLiteral("run1/smooth"),
                                  params({{"cutoff", "5"}, {"order", "4"}})});
    ASSERT_TRUE(filtered.ok()) << filtered.message().toStdString();
    EXPECT_EQ(project_->stream(QStringLiteral("run1/smooth"))->info().provenance.processorId,
              QStringLiteral("butterworth"));
}
