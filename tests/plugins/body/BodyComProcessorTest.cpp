// body-model and body-com through the runner (issue #18 items 1–2): true sensor orientations of the simulated
// skier with the true mounts and sensor-to-joint vectors reproduce the simulator's CoM; bad inputs are refused
// with a message naming what is wrong.
#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/body/BodyComProcessor.h"
#include "plugins/body/BodyModelProcessor.h"
#include "plugins/body/WholeBodySimulator.h"
#include "plugins/inertial/SimulateBodyProcessor.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::body;

namespace {
Expected<RunOutcome> run(Project& project, const Processor& p, QStringList inputs, QString output,
                         QVariantMap params = {}) {
    return runProcessor(project, p, RunRequest{p.id(), inputs, output, params});
}

Stream orientationStream(const std::vector<double>& t, const std::vector<Quat>& q) {
    StreamData d(t.size(), 4);
    d.t = t;
    for (std::size_t k = 0; k < t.size(); ++k) {
        d.at(k, 0) = q[k].w();
        d.at(k, 1) = q[k].x();
        d.at(k, 2) = q[k].y();
        d.at(k, 3) = q[k].z();
    }
    return outputStream(QStringLiteral("orientation"), QStringLiteral("ENU"),
                        columnsOf({"qw", "qx", "qy", "qz"}, {"1", "1", "1", "1"}), std::move(d));
}
}  // namespace

TEST(BodyComProcessor, TrueOrientationsEndToEndAndRefusals) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("b.athlos"));
    ASSERT_TRUE(project);
    // The simulator's tables (true mounts, sensor-to-joint vectors) through simulate-body …
    const inertial::SimulateBodyProcessor simulate;
    ASSERT_TRUE(run(*project, simulate, {}, "ski/imu", {{"seed", 3}, {"motion_duration", 12.0}, {"squats", 1}}));
    // … and the same run's true sensor orientations and helmet antenna from the whole-body layer.
    WholeBodyParams wp;
    wp.body.seed = 3;
    wp.body.motionDuration = 12.0;
    wp.body.squats = 1;
    wp.height = 1.80;
    wp.mass = 78.0;
    wp.equipment[int(Segment::Head)] = 0.5;
    wp.equipment[int(Segment::RightFoot)] = wp.equipment[int(Segment::LeftFoot)] = 3.0;
    const WholeBodySimulation w = simulateWholeBody(wp);
    ASSERT_FALSE(w.com.empty());
    const char* names[] = {"sacrum",     "sternum",    "right-thigh", "right-shank",
                           "right-foot", "left-thigh", "left-shank",  "left-foot"};
    const char* segments[] = {"pelvis",     "thorax",     "right-thigh", "right-shank",
                              "right-foot", "left-thigh", "left-shank",  "left-foot"};
    QStringList sensors;
    for (int s = 0; s < 8; ++s) {
        const QString path = QStringLiteral("ski/%1-orientation").arg(QLatin1String(names[s]));
        project->putStream(path, orientationStream(w.body.t, w.body.sensors[s].sensor));
        sensors << QStringLiteral("%1:%2").arg(QLatin1String(segments[s]), path);
    }
    {
        StreamData d(w.gnssT.size(), 3);
        d.t = w.gnssT;
        for (std::size_t k = 0; k < w.gnss.size(); ++k)
            for (int i = 0; i < 3; ++i) d.at(k, i) = w.gnss[k][i];
        project->putStream("ski/gnss", outputStream(QStringLiteral("gnss"), QStringLiteral("ENU"),
                                                    columnsOf({"x", "y", "z"}, {"m", "m", "m"}), std::move(d)));
    }
    const BodyModelProcessor model;
    const BodyComProcessor com;
    const QVariantMap modelParams{{"height", 1.80},
                                  {"mass", 78.0},
                                  {"sensors", sensors.join(',')},
                                  {"equipment", "head:0.5,right-foot:3,left-foot:3"},
                                  {"antenna", "head:ski/gnss"}};
    auto made = run(*project, model, {}, "ski/body", modelParams);
    ASSERT_TRUE(made) << made.message().toStdString();
    auto done = run(*project, com, {"ski/body", "ski/imu-right-mounts", "ski/imu-left-mounts", "ski/imu-joint-vectors"},
                    "ski/com");
    ASSERT_TRUE(done) << done.message().toStdString();
    auto data = project->stream("ski/com")->data();
    ASSERT_TRUE(data);
    const StreamData& d = **data;
    ASSERT_EQ(d.rows(), w.com.size());
    double sq = 0;
    for (std::size_t k = 0; k < d.rows(); ++k)
        sq += (Vec3(d.at(k, 0), d.at(k, 1), d.at(k, 2)) - w.com[k]).squaredNorm();
    EXPECT_LT(std::sqrt(sq / double(d.rows())), 0.003);  // arm/head swing only (≈ 1 mm)
    // Absolute CoM against the truth (GNSS noise 2 cm white + 3 cm wander).
    auto absolute = project->stream("ski/com-absolute")->data();
    ASSERT_TRUE(absolute);
    double asq = 0;
    for (std::size_t r = 0; r < (*absolute)->rows(); ++r) {
        const std::size_t k = std::size_t(std::lround((*absolute)->t[r] * wp.body.rate));
        asq += (Vec3((*absolute)->at(r, 0), (*absolute)->at(r, 1), (*absolute)->at(r, 2)) - (w.lumbar[k] + w.com[k]))
                   .squaredNorm();
    }
    EXPECT_LT(std::sqrt(asq / double((*absolute)->rows())), 0.08);
    // The eight orientation streams and the antenna stream the body model names are inputs of the result
    // (provenance, athlos batch's skip rule), after the four declared inputs.
    const auto& inputs = project->stream("ski/com")->info().provenance.inputs;
    ASSERT_EQ(inputs.size(), 4u + 8u + 1u);
    EXPECT_EQ(inputs[4].name, QStringLiteral("ski/sacrum-orientation"));
    EXPECT_EQ(inputs[4].hash, project->stream("ski/sacrum-orientation")->info().contentHash);
    EXPECT_EQ(inputs.back().name, QStringLiteral("ski/gnss"));
    // Without the sensor-to-joint vectors the table's (different) segment lengths are used: a larger error.
    ASSERT_TRUE(run(*project, com, {"ski/body", "ski/imu-right-mounts", "ski/imu-left-mounts"}, "ski/com-table"));
    auto table = project->stream("ski/com-table")->data();
    double tsq = 0;
    for (std::size_t k = 0; k < (*table)->rows(); ++k)
        tsq += (Vec3((*table)->at(k, 0), (*table)->at(k, 1), (*table)->at(k, 2)) - w.com[k]).squaredNorm();
    EXPECT_GT(std::sqrt(tsq / double((*table)->rows())), 0.01);

    // Refusals name the culprit.
    const auto fails = [&](const Processor& p, QStringList in, QVariantMap params, const char* pattern) {
        auto r = run(*project, p, in, "ski/bad", params);
        ASSERT_FALSE(r);
        EXPECT_TRUE(r.message().contains(QLatin1String(pattern))) << r.message().toStdString();
    };
    QVariantMap bad = modelParams;
    bad["sensors"] = "pelvis:ski/nothing";
    fails(model, {}, bad, "ski/nothing");
    bad["sensors"] = "tail:ski/sacrum-orientation";
    fails(model, {}, bad, "tail");
    bad["sensors"] = "pelvis:ski/imu";  // an IMU, not an orientation
    fails(model, {}, bad, "orientation");
    bad = modelParams;
    bad["height"] = 2.9;
    fails(model, {}, bad, "height");
    bad = modelParams;
    bad["sensors"] = "pelvis:ski/sacrum-orientation,thorax:ski/sternum-orientation";
    ASSERT_TRUE(run(*project, model, {}, "ski/legless", bad));
    fails(com, {"ski/legless"}, {}, "right-thigh");
    project->putTable("ski/not-a-model", project->table("ski/imu-joint-vectors")
                                             ? *project->table("ski/imu-joint-vectors")
                                             : athlos::Table{});
    fails(com, {"ski/not-a-model"}, {}, "body-model");
}
