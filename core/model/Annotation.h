#pragma once
#include <QString>
#include <vector>

namespace athlos {

// A labelled interval (or instant, tEnd == tStart) on a recording's time axis.
struct Annotation {
    QString label;
    double tStart = 0.0;  // s
    double tEnd = 0.0;    // s
    QString annotator;
    double confidence = 1.0;                    // [0, 1]
    QString source = QStringLiteral("manual");  // "manual" or a processor id
    bool operator==(const Annotation&) const = default;
};

using Annotations = std::vector<Annotation>;

}  // namespace athlos
