#pragma once
// CSV import, part 3 of 3: time-order repair (also used by other text importers). Samples whose
// time stamps do not increase are rejected, sorted or dropped, and every message names the line.
#include "core/model/StreamData.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace athlos {

// Where the time stamps of parsed samples came from, for messages.
struct TimeOrigin {
    QString file;
    int column = 1;  // 1-based column of t
    QString columnName = QStringLiteral("t");
    std::vector<long long> lines;  // line of each sample
};

// Makes times increasing according to mode (ImportOptions::timeRepair):
//   reject: error naming the first offending line and both times;
//   sort:   stable sort by time; exact duplicate samples are dropped with a warning, samples with
//           equal times but different values are an error (unless allowEqualTimes);
//   drop:   drops every sample whose time is not after the last kept one, with a warning.
// allowEqualTimes accepts equal consecutive times (long-format rows such as TDoA's).
// Warnings are appended to warnings.
Status repairTimeOrder(StreamData& data, TimeOrigin& origin, const QString& mode, bool allowEqualTimes,
                       QStringList& warnings);

}  // namespace athlos
