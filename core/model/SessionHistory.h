#pragma once
// An athlete's sessions over time against a rolling baseline (`athlos history`): for every session
// and metric, the mean of the same athlete's sessions in the `baselineDays` before it (the chronic
// load of the acute:chronic workload ratio, Hulin et al. 2016 / Gabbett 2016, Br J Sports Med
// 50:273–280, with a 4-week window), the ratio session / baseline, and a flag when the ratio leaves the
// band [lowRatio, highRatio] (Gabbett's "sweet spot" 0.8–1.3 and "danger zone" above 1.5).
#include "core/model/Table.h"
#include "core/util/Expected.h"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <map>
#include <vector>

namespace athlos {

struct SessionRecord {
    QString athlete;
    QString session;                   // "project: rec/stream-metrics", shown in the table
    QDateTime date;                    // UTC
    std::map<QString, double> values;  // metric → value (the metrics table's `whole` row)
};

class SessionHistory {
public:
    struct Params {
        double baselineDays = 28.0;  // rolling window before the session (4 weeks)
        double lowRatio = 0.8;       // Gabbett 2016: below the sweet spot
        double highRatio = 1.5;      // Gabbett 2016: danger zone
        QStringList metrics{QStringLiteral("distance"), QStringLiteral("hsr_distance"), QStringLiteral("sprint_count"),
                            QStringLiteral("max_speed")};
    };

    // Rows sorted by athlete, then date: athlete, session, date (ISO 8601), and per metric <m>,
    // <m>_baseline (NaN without an earlier session in the window), <m>_ratio, and `flags` ("distance
    // high; max_speed low"). Error if a metric is missing from every record.
    static Expected<Table> build(std::vector<SessionRecord> records, const Params& params);
};

}  // namespace athlos
