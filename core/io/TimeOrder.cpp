#include "core/io/TimeOrder.h"

#include "core/io/CsvColumns.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace athlos {
namespace {

using csv::shortest;
using csv::where;

void keepRows(StreamData& data, std::vector<long long>& lines, const std::vector<size_t>& rows) {
    StreamData kept(rows.size(), data.columns);
    std::vector<long long> keptLines(rows.size());
    const size_t width = size_t(data.columns);
    for (size_t i = 0; i < rows.size(); ++i) {
        kept.t[i] = data.t[rows[i]];
        keptLines[i] = lines[rows[i]];
        std::copy_n(data.values.begin() + ptrdiff_t(rows[i] * width), width,
                    kept.values.begin() + ptrdiff_t(i * width));
    }
    data = std::move(kept);
    lines = std::move(keptLines);
}

bool sameSample(const StreamData& data, size_t a, size_t b) {
    const size_t width = size_t(data.columns);
    return std::memcmp(&data.t[a], &data.t[b], sizeof(double)) == 0 &&
           std::memcmp(data.values.data() + a * width, data.values.data() + b * width, width * sizeof(double)) == 0;
}

}  // namespace

Status repairTimeOrder(StreamData& data, TimeOrigin& origin, const QString& mode, bool allowEqualTimes,
                       QStringList& warnings) {
    auto inOrder = [allowEqualTimes](double previous, double next) {
        return allowEqualTimes ? next >= previous : next > previous;
    };
    const size_t n = data.rows();
    if (origin.lines.size() != n)
        return makeError(QStringLiteral("%1: internal error: %2 line numbers for %3 samples")
                             .arg(origin.file)
                             .arg(origin.lines.size())
                             .arg(n));
    size_t first = 1;
    while (first < n && inOrder(data.t[first - 1], data.t[first])) ++first;
    if (first >= n) return {};

    const QString at = where(origin.file, origin.lines[first], origin.column, origin.columnName);
    if (mode == QLatin1String("reject")) {
        return makeError(QStringLiteral("%1: time %2 is not after %3 on line %4 (times must increase; "
                                        "repair with time repair 'sort' or 'drop')")
                             .arg(at, shortest(data.t[first]), shortest(data.t[first - 1]))
                             .arg(origin.lines[first - 1]));
    }
    std::vector<size_t> rows;
    rows.reserve(n);
    if (mode == QLatin1String("drop")) {
        for (size_t i = 0; i < n; ++i)
            if (rows.empty() || inOrder(data.t[rows.back()], data.t[i])) rows.push_back(i);
        warnings << QStringLiteral(
                        "%1: dropped %2 samples whose time was not after the previous sample's (first on line %3)")
                        .arg(origin.file)
                        .arg(n - rows.size())
                        .arg(origin.lines[first]);
        keepRows(data, origin.lines, rows);
        return {};
    }
    if (mode != QLatin1String("sort"))
        return makeError(QStringLiteral("unknown time repair '%1' (reject, sort or drop)").arg(mode));

    size_t outOfOrder = 0;
    for (size_t i = 1; i < n; ++i) outOfOrder += data.t[i] < data.t[i - 1];
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return data.t[a] < data.t[b]; });
    size_t duplicates = 0;
    size_t group = 0;  // first kept row (index into rows) with the current time
    for (size_t i : order) {
        if (rows.empty() || data.t[i] != data.t[rows.back()]) {
            group = rows.size();
            rows.push_back(i);
            continue;
        }
        bool duplicate = false;
        for (size_t k = group; k < rows.size() && !duplicate; ++k) duplicate = sameSample(data, rows[k], i);
        if (duplicate) {
            ++duplicates;
        } else if (allowEqualTimes) {
            rows.push_back(i);
        } else {
            return makeError(QStringLiteral("%1: lines %2 and %3 have the same time %4 but different values; "
                                            "time repair 'drop' keeps the first")
                                 .arg(origin.file)
                                 .arg(origin.lines[rows.back()])
                                 .arg(origin.lines[i])
                                 .arg(shortest(data.t[i])));
        }
    }
    if (outOfOrder > 0)
        warnings << QStringLiteral("%1: sorted by time (%2 samples were out of order, the first on line %3)")
                        .arg(origin.file)
                        .arg(outOfOrder)
                        .arg(origin.lines[first]);
    if (duplicates > 0)
        warnings << QStringLiteral("%1: dropped %2 exact duplicate samples").arg(origin.file).arg(duplicates);
    keepRows(data, origin.lines, rows);
    return {};
}

}  // namespace athlos
