#pragma once
// A trained model stored in a project (/models/<name>): an opaque definition in a data format that
// its owner parses (e.g. OpenCV's cv::FileStorage YAML text of a classifier) plus a JSON
// description (classes, features, scaling, window, classifier, training recordings with their
// content hashes, cross-validation metrics, app version, time). Nothing stored is executed: the
// store only keeps the bytes, and readers parse data formats, never code.
#include <QByteArray>
#include <QJsonObject>
#include <QString>

namespace athlos {

struct TrainedModel {
    // A definition larger than this is refused when a project is opened: models trained in Athlos
    // are a few MB (a random forest of 100 trees on 10^5 windows is ~20 MB of YAML), so anything
    // near 256 MiB is a damaged or hostile file, refused before its bytes are allocated.
    static constexpr long long kMaxDefinitionBytes = 256LL * 1024 * 1024;

    QString name;
    QString format;  // how `definition` is encoded, e.g. "opencv-yaml"
    QByteArray definition;
    QJsonObject description;
    bool operator==(const TrainedModel&) const = default;
};

}  // namespace athlos
