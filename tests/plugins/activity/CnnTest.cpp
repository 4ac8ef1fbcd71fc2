// The CNN path: the committed tiny ONNX network gives PyTorch's probabilities through OpenCV dnn,
// classifies simulated people far above chance, survives the project file, and bad networks are
// refused with a reason.
#include "plugins/activity/CnnTraining.h"
#include "plugins/activity/ClassifyActionsProcessor.h"
#include "plugins/activity/RawWindows.h"

#include "core/processing/ProcessorRunner.h"
#include "tests/plugins/activity/SimulatedProject.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::activity;
using namespace athlos::activity::test;

namespace {

QByteArray readData(const QString& name) {
    QFile f(QStringLiteral(ATHLOS_TEST_DATA_DIR "/activity/") + name);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << qPrintable(f.fileName());
    return f.readAll();
}

QJsonObject description() { return QJsonDocument::fromJson(readData(QStringLiteral("tiny_cnn.json"))).object(); }

Expected<ActivityModel> tinyModel() {
    return importCnn(readData(QStringLiteral("tiny_cnn.onnx")), description(), QStringLiteral("tiny_cnn.onnx"));
}

}  // namespace

TEST(CnnTest, GivesThePyTorchProbabilities) {
    auto model = tinyModel();
    ASSERT_TRUE(model.ok()) << qPrintable(model.message());
    ASSERT_TRUE(model->cnn.has_value());
    const QJsonObject reference = QJsonDocument::fromJson(readData(QStringLiteral("tiny_cnn.reference.json"))).object();
    const QJsonArray windows = reference.value(QStringLiteral("windows")).toArray();
    const QJsonArray expected = reference.value(QStringLiteral("probabilities")).toArray();
    ASSERT_GE(windows.size(), 4);
    const int c = model->cnn->channels(), l = model->cnn->length();
    cv::Mat raw(int(windows.size()), c * l, CV_32F);
    for (int i = 0; i < raw.rows; ++i) {
        const QJsonArray channels = windows[i].toArray();
        ASSERT_EQ(channels.size(), c);
        for (int ch = 0; ch < c; ++ch) {
            const QJsonArray values = channels[ch].toArray();
            ASSERT_EQ(values.size(), l);
            for (int j = 0; j < l; ++j) raw.at<float>(i, ch * l + j) = float(values[j].toDouble());
        }
    }
    cv::Mat p;
    ASSERT_TRUE(model->cnn->probabilities(raw, p).ok());
    ASSERT_EQ(p.rows, raw.rows);
    ASSERT_EQ(p.cols, int(model->classes.size()));
    double worst = 0;
    for (int i = 0; i < p.rows; ++i)
        for (int k = 0; k < p.cols; ++k)
            worst = std::max(worst, std::abs(double(p.at<float>(i, k)) - expected[i].toArray()[k].toDouble()));
    EXPECT_LT(worst, 1e-4);
}

TEST(CnnTest, ClassifiesSimulatedPeopleAndSurvivesTheProjectFile) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = Project::create(path);
    std::vector<SimulatedRecording> sims;
    for (unsigned person = 201; person <= 203; ++person)
        sims.push_back(addSimulated(*project, QStringLiteral("r%1").arg(person), person, 7, true));
    auto model = tinyModel();
    ASSERT_TRUE(model.ok()) << qPrintable(model.message());
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
    TrainingOptions options;
    options.window = model->window;
    options.step = model->step;
    options.sensors = model->sensors;
    auto raw = buildRawDataset(*sources, options, model->classes, model->cnn->length());
    ASSERT_TRUE(raw.ok()) << qPrintable(raw.message());
    cv::Mat p;
    ASSERT_TRUE(model->cnn->probabilities(raw->windows, p).ok());
    std::vector<int> predicted;
    for (int i = 0; i < p.rows; ++i) {
        const float* row = p.ptr<float>(i);
        predicted.push_back(int(std::max_element(row, row + p.cols) - row));
    }
    const Evaluation e = evaluate(raw->labels, predicted, model->classes);
    // 7 classes (chance 0.14); the 5.6 kB network reaches about 0.8 on people it never saw.
    EXPECT_GT(e.balancedAccuracy, 0.6) << qPrintable(e.toText());

    // classify-actions with the stored model; the same annotations after save and reopen.
    auto stored = model->toStored(QStringLiteral("cnn"));
    ASSERT_TRUE(stored.ok()) << qPrintable(stored.message());
    project->models()[QStringLiteral("cnn")] = *stored;
    ClassifyActionsProcessor processor;
    const RunRequest request{processor.id(),
                             {QStringLiteral("r201/imu")},
                             QStringLiteral("r201/actions"),
                             {{QStringLiteral("model"), QStringLiteral("cnn")}}};
    project->recording(QStringLiteral("r201"))->annotations.clear();
    auto first = runProcessor(*project, processor, request);
    ASSERT_TRUE(first.ok()) << qPrintable(first.message());
    const Annotations before = project->recording(QStringLiteral("r201"))->annotations;
    ASSERT_FALSE(before.empty());
    EXPECT_GT(sampleBalancedAccuracy(sims[0].imu.t, sims[0].labels, before), 0.6);
    ASSERT_TRUE(project->save().ok());
    auto reopened = Project::open(path);
    ASSERT_TRUE(reopened.ok()) << qPrintable(reopened.message());
    EXPECT_EQ(*(*reopened)->model(QStringLiteral("cnn")), *stored);
    (*reopened)->recording(QStringLiteral("r201"))->annotations.clear();
    auto again = runProcessor(**reopened, processor, request);
    ASSERT_TRUE(again.ok()) << qPrintable(again.message());
    EXPECT_EQ((*reopened)->recording(QStringLiteral("r201"))->annotations, before);
}

TEST(CnnTest, RefusesNetworksThatDoNotFit) {
    const QByteArray onnx = readData(QStringLiteral("tiny_cnn.onnx"));
    const auto refused = [&](const QByteArray& bytes, const QJsonObject& d) {
        auto m = importCnn(bytes, d, QStringLiteral("x.onnx"));
        return m.ok() ? QString() : m.message();
    };
    EXPECT_TRUE(refused(onnx, description()).isEmpty());
    EXPECT_TRUE(refused(QByteArray(CnnClassifier::kMaxOnnxBytes + 1, 'x'), description()).contains(u"above the limit"));
    EXPECT_TRUE(refused("not a network", description()).contains(u"cv::dnn cannot read"));
    QJsonObject fewerClasses = description();
    QJsonArray classes = fewerClasses.value(QStringLiteral("classes")).toArray();
    classes.removeLast();
    fewerClasses[QStringLiteral("classes")] = classes;
    EXPECT_TRUE(refused(onnx, fewerClasses).contains(u"outputs per window for 6 classes"))
        << qPrintable(refused(onnx, fewerClasses));
    QJsonObject longer = description();
    QJsonObject cnn = longer.value(QStringLiteral("cnn")).toObject();
    cnn[QStringLiteral("length")] = 64;
    longer[QStringLiteral("cnn")] = cnn;
    EXPECT_FALSE(refused(onnx, longer).isEmpty());
    QJsonObject noScale = description();
    cnn = noScale.value(QStringLiteral("cnn")).toObject();
    cnn[QStringLiteral("scale")] = QJsonArray{1.0, 0.0, 1.0};
    noScale[QStringLiteral("cnn")] = cnn;
    EXPECT_TRUE(refused(onnx, noScale).contains(u"normalisation")) << qPrintable(refused(onnx, noScale));
}

TEST(RawWindowsTest, ResamplesLinearlyAndWritesNpy) {
    StreamData data(11, 2);
    for (std::size_t i = 0; i < 11; ++i) {
        data.t[i] = 0.1 * double(i);
        data.at(i, 0) = double(i);
        data.at(i, 1) = -2.0 * double(i);
    }
    float out[2 * 5];
    rawWindow(data, {1, 0}, 0.2, 0.6, 5, out);  // 0.2, 0.3, …, 0.6 s
    for (int j = 0; j < 5; ++j) {
        EXPECT_NEAR(out[j], -2.0 * (2 + j), 1e-4);
        EXPECT_NEAR(out[5 + j], 2 + j, 1e-4);
    }
    rawWindow(data, {0}, 0.95, 1.5, 3, out);  // beyond the end: the last sample
    EXPECT_NEAR(out[0], 9.5, 1e-4);
    EXPECT_NEAR(out[2], 10.0, 1e-6);
    QTemporaryDir dir;
    const int values[3] = {1, 2, 3};
    ASSERT_TRUE(writeNpy(dir.filePath(QStringLiteral("a.npy")), {3}, values).ok());
    QFile f(dir.filePath(QStringLiteral("a.npy")));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    const qsizetype header = bytes.size() - 12;  // padded to a multiple of 64 bytes, then the data
    EXPECT_EQ(header % 64, 0);
    EXPECT_TRUE(bytes.startsWith(QByteArray("\x93NUMPY\x01\x00", 8)));
    EXPECT_EQ(int(quint8(bytes.at(8))) + 256 * int(quint8(bytes.at(9))), header - 10);
    EXPECT_TRUE(bytes.contains("'shape': (3,)"));
    EXPECT_EQ(bytes.at(header - 1), '\n');
    EXPECT_EQ(bytes.mid(header, 4), QByteArray("\x01\x00\x00\x00", 4));
}
