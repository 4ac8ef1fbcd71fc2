#pragma once
// The classifier comparison table of the activity evaluations (athlos-eval-activity,
// athlos-eval-event-detectors; docs/validation/activity.md): cross-validated balanced accuracy,
// accuracy and time per classifier and, with `selections`, per number of features kept by mutual
// information (0: all). Printed as a Markdown table on stdout.
#include "plugins/activity/ActivityTraining.h"

#include <QStringList>
#include <vector>

namespace athlos::activity {

// accuracyHeader names the balanced-accuracy column, e.g. "balanced accuracy (leave-one-subject-out)".
// Returns 1 when the cross-validation folds cannot be formed (the message on stderr), else 0.
int printClassifierComparison(const Dataset& dataset, const std::vector<TrainingSource>& sources,
                              const TrainingOptions& options, const QStringList& classifiers,
                              const std::vector<int>& selections, const char* accuracyHeader);

}  // namespace athlos::activity
