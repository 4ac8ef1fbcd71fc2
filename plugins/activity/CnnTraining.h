#pragma once
// The CNN's side of training (seed 000 §5.2; digest §8): Athlos cuts the labelled raw windows and
// exports them for scripts/train_cnn.py, which trains the network and writes ONNX plus a JSON
// description; Athlos imports that pair, checks it against the project's streams and evaluates it.
//
// Export format (a directory, read with numpy.load):
//   windows.npy  float32 N × C × L   raw windows, channels = input_columns, in the stream's units
//   labels.npy   int32   N           class index into meta.json "classes"
//   groups.npy   int32   N           subject index into meta.json "subjects" (for leave-subjects-out)
//   meta.json    classes, subjects, recordings, input_columns, sensors, units, window, step, length,
//                segmentation, format "athlos-windows-1"
#include "plugins/activity/ActivityTraining.h"

#include <QByteArray>
#include <QJsonObject>

namespace athlos::activity {

struct RawDataset {
    cv::Mat windows;          // N × (C·L) CV_32F, channel major per row
    std::vector<int> labels;  // class per window
    std::vector<int> source;  // index into the sources
    std::vector<int> groups;  // subject (athlete) index
    QStringList classes, inputColumns, sensors, subjects;
    QJsonObject units;
    int length = 0;  // samples per channel
    Segmentation segmentation;
};

// Labelled raw windows. `classes` empty: options' classes or every label, unseen ones dropped;
// else exactly these (a model's), windows of other labels left out. `length` 0: options.rawLength or
// the window at the first source's median rate.
Expected<RawDataset> buildRawDataset(const std::vector<TrainingSource>& sources, const TrainingOptions& options,
                                     const QStringList& classes = {}, int length = 0, const Progress& progress = {});

Status exportWindows(const RawDataset& dataset, const std::vector<TrainingSource>& sources,
                     const TrainingOptions& options, const QString& directory);

// A model from an ONNX network and its description (train_cnn.py's JSON); `what` names the files in
// errors. Checks the classes, columns, window, normalisation and the network itself (CnnClassifier).
Expected<ActivityModel> importCnn(const QByteArray& onnx, const QJsonObject& description, const QString& what);

}  // namespace athlos::activity
