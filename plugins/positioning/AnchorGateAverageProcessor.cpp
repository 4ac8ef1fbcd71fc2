#include "plugins/positioning/AnchorGateAverageProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/positioning/GateAveraging.h"
#include "plugins/positioning/GateTable.h"

#include <cmath>

namespace athlos::positioning {

namespace {
constexpr Translator tr{"athlos::positioning", "AnchorGateAverageProcessor"};
constexpr int kRuns = 8;
}  // namespace

QString AnchorGateAverageProcessor::name() const { return tr("Average gate positions over runs (GNSS-free)"); }

QString AnchorGateAverageProcessor::description() const {
    return tr(
        "GNSS-free gate positions (Fasel thesis ch. 10): the gate estimates of several anchor-smoother runs, each "
        "aligned and scaled to the mean first and last gates, averaged gate by gate.");
}

QList<InputSpec> AnchorGateAverageProcessor::inputs() const {
    QList<InputSpec> specs;
    for (int r = 1; r <= kRuns; ++r)
        specs.append(InputSpec{QStringLiteral("run%1").arg(r),
                               {QStringLiteral("gate-crossings")},
                               true,
                               r > 2,
                               tr("Crossings table of an anchor-smoother run.")});
    return specs;
}

QList<OutputSpec> AnchorGateAverageProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("gates"), true, QString(), tr("Averaged gates: id, east, north, up (m).")}};
}

Expected<std::vector<ProcessorOutput>> AnchorGateAverageProcessor::run(const RunContext& c) const {
    std::vector<std::vector<math::Vec3>> runs;
    for (int r = 0; r < c.inputCount(); ++r) {
        const Table* table = c.table(r);
        if (!table) continue;
        const TableColumn* cols[3] = {table->column(QStringLiteral("est_east")),
                                      table->column(QStringLiteral("est_north")),
                                      table->column(QStringLiteral("est_up"))};
        if (!cols[0] || !cols[1] || !cols[2] || cols[0]->isText || cols[1]->isText || cols[2]->isText)
            return c.inputError(r,
                                QStringLiteral("needs numeric columns est_east, est_north, est_up (an anchor-smoother "
                                               "crossings table)"));
        std::vector<math::Vec3> gates;
        for (long long m = 0; m < table->rows(); ++m) {
            const math::Vec3 g(cols[0]->numbers[std::size_t(m)], cols[1]->numbers[std::size_t(m)],
                               cols[2]->numbers[std::size_t(m)]);
            if (!g.allFinite())
                return c.inputError(r, QStringLiteral("row %1: the gate estimate is not finite").arg(m + 1));
            gates.push_back(g);
        }
        runs.push_back(std::move(gates));
    }
    auto mean = GateAveraging::average(runs);
    if (!mean) return mean.error();
    std::vector<Gate> gates;
    for (std::size_t m = 0; m < mean->size(); ++m)
        gates.push_back({QStringLiteral("G%1").arg(int(m) + 1, 2, 10, QLatin1Char('0')), (*mean)[m]});
    Table table = gatesTable(gates);
    table.attributes = QJsonObject{{QStringLiteral("runs"), int(runs.size())},
                                   {QStringLiteral("method"), QStringLiteral("gnss-free average (Fasel ch. 10)")}};
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(table)});
    return outputs;
}

}  // namespace athlos::positioning
