#include "plugins/events/GaitSummaryProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/events/GaitSummary.h"

#include <QJsonArray>
#include <cmath>
#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "GaitSummaryProcessor"};

const QString kStrideKind = QStringLiteral("gait-parameters");

struct Plan {
    GaitSummaryParams params;
    std::vector<FootStrides> feet;
};

// A gait-parameters table as one foot's strides: start, end and turning_angle, and every other numeric
// column as a parameter.
Expected<FootStrides> footOf(const RunContext& c, int input, const Table& table, Terrain terrain) {
    FootStrides f;
    f.foot = table.attributes.value(QStringLiteral("foot")).toString();
    if (f.foot.isEmpty()) f.foot = input == 0 ? QStringLiteral("strides") : QStringLiteral("other");
    for (const char* name : {"start", "end", "turning_angle"}) {
        const TableColumn* column = table.column(QLatin1String(name));
        if (!column || column->isText)
            return c.inputError(input, QStringLiteral("no numeric column '%1' (a gait-parameters table has start, "
                                                      "end and turning_angle)")
                                           .arg(QLatin1String(name)));
    }
    f.start = table.column(QStringLiteral("start"))->numbers;
    f.end = table.column(QStringLiteral("end"))->numbers;
    f.turn = table.column(QStringLiteral("turning_angle"))->numbers;
    if (const TableColumn* height = table.column(QStringLiteral("stride_height")); height && !height->isText)
        f.height = height->numbers;
    else if (terrain != Terrain::All)
        return c.inputError(input, QStringLiteral("terrain: needs a numeric column stride_height"));
    for (const TableColumn& column : table.columns) {
        if (column.isText || column.name == QLatin1String("start") || column.name == QLatin1String("end") ||
            column.name == QLatin1String("turning_angle"))
            continue;
        f.names << column.name;
        f.units << column.unit;
        f.parameters.push_back(column.numbers);
    }
    return f;
}

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    plan.params.maxTurn = c.number(QStringLiteral("max_turn"));
    plan.params.edgeStrides = c.integer(QStringLiteral("edge_strides"));
    const auto terrain = terrainOf(c.text(QStringLiteral("terrain")));
    if (!terrain)
        return makeError(
            QStringLiteral("terrain: '%1' is not one of all, level, up, down").arg(c.text(QStringLiteral("terrain"))));
    plan.params.terrain = *terrain;
    plan.params.levelHeight = c.number(QStringLiteral("level_height"));
    plan.params.stairHeight = c.number(QStringLiteral("stair_height"));
    if (plan.params.stairHeight <= plan.params.levelHeight)
        return makeError(QStringLiteral("stair_height: %1 m must be above level_height (%2 m)")
                             .arg(plan.params.stairHeight)
                             .arg(plan.params.levelHeight));
    auto first = c.requireTable(0);
    if (!first) return first.error();
    const Table* tables[2] = {*first, c.table(1)};  // the other foot is optional
    for (int input = 0; input < 2; ++input) {
        if (!tables[input]) continue;
        auto foot = footOf(c, input, *tables[input], plan.params.terrain);
        if (!foot) return foot.error();
        plan.feet.push_back(std::move(*foot));
    }
    if (plan.feet.size() == 2 && plan.feet[0].foot == plan.feet[1].foot)
        return c.inputError(
            1, QStringLiteral("is also the %1 foot: give the other foot's strides").arg(plan.feet[0].foot));
    return plan;
}

TableColumn numberColumn(const QString& name, const QString& unit) { return TableColumn{name, unit, false, {}, {}}; }

void addRow(std::vector<TableColumn>& columns, const FootSummary& s, const std::vector<double>& symmetry) {
    columns[0].texts << s.foot;
    columns[1].numbers.push_back(s.strides);
    columns[2].numbers.push_back(s.used);
    std::size_t c = 3;
    const std::size_t per = symmetry.empty() ? 3 : 4;
    for (std::size_t p = 0; p < s.stats.size(); ++p) {
        columns[c + per * p].numbers.push_back(s.stats[p].mean);
        columns[c + per * p + 1].numbers.push_back(s.stats[p].sd);
        columns[c + per * p + 2].numbers.push_back(s.stats[p].cv);
        if (per == 4) columns[c + per * p + 3].numbers.push_back(symmetry[p]);
    }
}
}  // namespace

QString GaitSummaryProcessor::name() const { return tr("Gait summary (steady state)"); }

QString GaitSummaryProcessor::description() const {
    return tr(
        "Steady-state summary of the stride tables of gait-parameters, one foot or both: turning strides, "
        "strides on other ground than the chosen terrain (level, stairs up or down) and the first and last "
        "strides of every straight run left out, then per parameter the mean, standard deviation and "
        "coefficient of variation per foot, and for two feet both feet together with the symmetry index "
        "(Robinson et al. 1987).");
}

ParameterSpecs GaitSummaryProcessor::parameters() const {
    const GaitSummaryParams d;
    return {
        ParameterSpec::number(QStringLiteral("max_turn"), d.maxTurn, 0.0, 3.2, QStringLiteral("rad"),
                              tr("Strides whose |turning_angle| is larger are turns and left out (0.3 rad = 17°, "
                                 "the straight strides of this project's validation).")),
        ParameterSpec::choice(
            QStringLiteral("terrain"),
            {QStringLiteral("all"), QStringLiteral("level"), QStringLiteral("up"), QStringLiteral("down")},
            QStringLiteral("all"),
            tr("Which strides to summarise by their stride_height: all, level (|height| at "
               "most level_height), up or down (|height| at least stair_height); the others, "
               "transitions included, are left out like turns.")),
        ParameterSpec::number(QStringLiteral("level_height"), d.levelHeight, 0.0, 10.0, QStringLiteral("m"),
                              tr("Largest |stride_height| of a level stride (a third of a step; level strides "
                                 "drift by 0.02-0.03 m).")),
        ParameterSpec::number(QStringLiteral("stair_height"), d.stairHeight, 0.0, 10.0, QStringLiteral("m"),
                              tr("Smallest |stride_height| of a stride on stairs: a stride climbs two steps of "
                                 "0.14-0.19 m (DIN 18065), a transition (one step and a landing) less.")),
        ParameterSpec::integer(QStringLiteral("edge_strides"), d.edgeStrides, 0, 100,
                               tr("Strides left out at each end of a run of adjacent straight strides: gait "
                                  "initiation and termination (steady state, Lindemann et al. 2008).")),
    };
}

QList<InputSpec> GaitSummaryProcessor::inputs() const {
    return {
        InputSpec{
            QStringLiteral("strides"), {kStrideKind}, true, false, tr("Stride table of one foot (gait-parameters).")},
        InputSpec{QStringLiteral("other"),
                  {kStrideKind},
                  true,
                  true,
                  tr("Stride table of the other foot (gait-parameters); with it, both feet together and the "
                     "symmetry index.")}};
}

QList<OutputSpec> GaitSummaryProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("gait-summary"), true, QString(),
                       tr("One row per foot (and both): foot, strides, used, then per parameter <p>_mean, <p>_sd, "
                          "<p>_cv (%) and, for two feet, <p>_si (%, in the row both).")}};
}

Status GaitSummaryProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> GaitSummaryProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const GaitSummary g = summariseGait(plan->params, plan->feet);
    // A summary of nothing is refused, not stored as a row of NaN.
    for (std::size_t f = 0; f < g.feet.size(); ++f)
        if (g.feet[f].used == 0)
            return context.inputError(int(f), QStringLiteral("no steady-state stride: %1 stride(s), %2 turning "
                                                             "(max_turn = %3 rad), %4 on other terrain (terrain = "
                                                             "%5), %6 at the ends of straight runs "
                                                             "(edge_strides = %7)")
                                                  .arg(g.feet[f].strides)
                                                  .arg(g.feet[f].turns)
                                                  .arg(plan->params.maxTurn)
                                                  .arg(g.feet[f].terrain)
                                                  .arg(context.text(QStringLiteral("terrain")))
                                                  .arg(g.feet[f].edges)
                                                  .arg(plan->params.edgeStrides));
    const bool two = g.feet.size() == 2;
    std::vector<TableColumn> columns{TableColumn{QStringLiteral("foot"), QString(), true, {}, {}},
                                     numberColumn(QStringLiteral("strides"), QStringLiteral("1")),
                                     numberColumn(QStringLiteral("used"), QStringLiteral("1"))};
    for (qsizetype p = 0; p < g.names.size(); ++p) {
        columns.push_back(numberColumn(g.names[p] + QStringLiteral("_mean"), g.units[p]));
        columns.push_back(numberColumn(g.names[p] + QStringLiteral("_sd"), g.units[p]));
        columns.push_back(numberColumn(g.names[p] + QStringLiteral("_cv"), QStringLiteral("%")));
        if (two) columns.push_back(numberColumn(g.names[p] + QStringLiteral("_si"), QStringLiteral("%")));
    }
    const std::vector<double> none(two ? g.names.size() : 0, std::numeric_limits<double>::quiet_NaN());
    for (const FootSummary& s : g.feet) addRow(columns, s, none);
    if (two) addRow(columns, g.pooled, g.symmetry);

    Table table;
    table.kind = QStringLiteral("gait-summary");
    QJsonArray turns, terrain, edges;
    for (const FootSummary& s : g.feet) {
        turns.append(s.turns);
        terrain.append(s.terrain);
        edges.append(s.edges);
    }
    table.attributes = QJsonObject{
        {QStringLiteral("max_turn"), plan->params.maxTurn},
        {QStringLiteral("edge_strides"), plan->params.edgeStrides},
        {QStringLiteral("turns_left_out"), turns},
        {QStringLiteral("terrain"), context.text(QStringLiteral("terrain"))},
        {QStringLiteral("level_height"), plan->params.levelHeight},
        {QStringLiteral("stair_height"), plan->params.stairHeight},
        {QStringLiteral("other_terrain_left_out"), terrain},
        {QStringLiteral("edges_left_out"), edges},
        {QStringLiteral("definitions"),
         QStringLiteral("sd: sample standard deviation (n - 1); cv = 100 sd / |mean|; si = 100 |mean_1 - mean_2| / "
                        "(0.5 |mean_1 + mean_2|) (Robinson et al. 1987), in the row both; cv and si only where "
                        "every value has the same sign (empty otherwise)")}};
    table.columns = std::move(columns);
    context.report(1.0);
    return std::vector<ProcessorOutput>{{QString(), std::move(table)}};
}

}  // namespace athlos::events
