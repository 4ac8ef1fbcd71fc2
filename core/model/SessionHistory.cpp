#include "core/model/SessionHistory.h"

#include <algorithm>
#include <cmath>

namespace athlos {

Expected<Table> SessionHistory::build(std::vector<SessionRecord> records, const Params& params) {
    for (const QString& m : params.metrics) {
        const bool any =
            std::any_of(records.begin(), records.end(), [&](const SessionRecord& r) { return r.values.count(m); });
        if (!any) return makeError(QStringLiteral("metric '%1' is in none of the sessions' tables").arg(m));
    }
    std::stable_sort(records.begin(), records.end(), [](const SessionRecord& a, const SessionRecord& b) {
        return a.athlete != b.athlete ? a.athlete < b.athlete : a.date < b.date;
    });
    Table table;
    table.name = QStringLiteral("history");
    table.kind = QStringLiteral("session-history");
    auto text = [&](const QString& name) { table.columns.push_back(TableColumn{name, QString(), true, {}, {}}); };
    text(QStringLiteral("athlete"));
    text(QStringLiteral("session"));
    text(QStringLiteral("date"));
    for (const QString& m : params.metrics) {
        table.columns.push_back(TableColumn{m, QString(), false, {}, {}});
        table.columns.push_back(TableColumn{m + QStringLiteral("_baseline"), QString(), false, {}, {}});
        table.columns.push_back(TableColumn{m + QStringLiteral("_ratio"), QStringLiteral("1"), false, {}, {}});
    }
    text(QStringLiteral("flags"));
    const double window = params.baselineDays * 86400.0;
    const double nan = std::nan("");
    for (std::size_t i = 0; i < records.size(); ++i) {
        const SessionRecord& r = records[i];
        table.columns[0].texts << r.athlete;
        table.columns[1].texts << r.session;
        table.columns[2].texts << r.date.toString(Qt::ISODate);
        QStringList flags;
        for (int k = 0; k < params.metrics.size(); ++k) {
            const QString& m = params.metrics[k];
            const auto it = r.values.find(m);
            const double value = it == r.values.end() ? nan : it->second;
            // Baseline: the athlete's earlier sessions within the window (records are sorted).
            double sum = 0.0;
            int n = 0;
            for (std::size_t j = i; j-- > 0 && records[j].athlete == r.athlete;) {
                const double age = double(records[j].date.secsTo(r.date));
                if (age > window) break;
                if (age <= 0) continue;  // same instant: not "before"
                const auto v = records[j].values.find(m);
                if (v != records[j].values.end() && std::isfinite(v->second)) sum += v->second, ++n;
            }
            const double baseline = n > 0 ? sum / n : nan;
            const double ratio = n > 0 && baseline != 0.0 ? value / baseline : nan;
            auto& columns = table.columns;
            columns[std::size_t(3 + 3 * k)].numbers.push_back(value);
            columns[std::size_t(4 + 3 * k)].numbers.push_back(baseline);
            columns[std::size_t(5 + 3 * k)].numbers.push_back(ratio);
            if (std::isfinite(ratio) && ratio > params.highRatio) flags << m + QStringLiteral(" high");
            if (std::isfinite(ratio) && ratio < params.lowRatio) flags << m + QStringLiteral(" low");
        }
        table.columns.back().texts << flags.join(QStringLiteral("; "));
    }
    return table;
}

}  // namespace athlos
