#include "plugins/lps/LpsAlignProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/lps/BeaconTable.h"
#include "plugins/lps/LpsInputs.h"

#include <QJsonArray>

namespace athlos::lps {

namespace {
constexpr Translator tr{"athlos::lps", "LpsAlignProcessor"};
}  // namespace

QString LpsAlignProcessor::name() const { return tr("LPS frame alignment"); }

QString LpsAlignProcessor::description() const {
    return tr(
        "Rotates and translates a beacon table so that venue marks (e.g. the finish line and a point down the "
        "home straight) land at the given coordinates.");
}

ParameterSpecs LpsAlignProcessor::parameters() const {
    return {ParameterSpec::text(QStringLiteral("marks"), QString(),
                                tr("Marks 'x,y,z>X,Y,Z; …': LPS coordinates > desired coordinates (m); "
                                   "or give a marks table as second input.")),
            ParameterSpec::choice(
                QStringLiteral("mode"), {QStringLiteral("yaw"), QStringLiteral("full")}, QStringLiteral("yaw"),
                tr("yaw: rotation about the vertical only (≥ 2 marks); full: 3D rotation (≥ 3 marks)."))};
}

QList<InputSpec> LpsAlignProcessor::inputs() const {
    return {InputSpec{QStringLiteral("beacons"), {QStringLiteral("beacons")}, true, false, tr("Beacon table to move.")},
            InputSpec{QStringLiteral("marks"),
                      {},
                      true,
                      true,
                      tr("Optional table x, y, z, target_x, target_y, target_z (m), one row per mark.")}};
}

QList<OutputSpec> LpsAlignProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("beacons"), true, QString(),
                       tr("Moved beacon table; a 'ref' row holds the moved reference node.")}};
}

Expected<std::pair<std::vector<Vector3>, std::vector<Vector3>>> LpsAlignProcessor::parseMarks(const QString& text) {
    std::pair<std::vector<Vector3>, std::vector<Vector3>> marks;
    auto point = [](const QString& s, Vector3& p) {
        const QStringList parts = s.split(QLatin1Char(','));
        if (parts.size() < 2 || parts.size() > 3) return false;
        p = Vector3::Zero();
        for (int k = 0; k < parts.size(); ++k) {
            bool ok = false;
            p(k) = parts[k].trimmed().toDouble(&ok);
            if (!ok) return false;
        }
        return true;
    };
    for (const QString& item : text.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QStringList sides = item.split(QLatin1Char('>'));
        Vector3 from, to;
        if (sides.size() != 2 || !point(sides[0], from) || !point(sides[1], to))
            return makeError(QStringLiteral("marks: '%1' is not 'x,y,z>X,Y,Z' (numbers in m)").arg(item.trimmed()));
        marks.first.push_back(from);
        marks.second.push_back(to);
    }
    return marks;
}

namespace {

Expected<std::pair<std::vector<Vector3>, std::vector<Vector3>>> collectMarks(const RunContext& context) {
    auto marks = LpsAlignProcessor::parseMarks(context.text(QStringLiteral("marks")));
    if (!marks) return marks;
    if (const Table* table = context.inputCount() > 1 ? context.table(1) : nullptr) {
        const char* names[] = {"x", "y", "z", "target_x", "target_y", "target_z"};
        const TableColumn* cols[6];
        for (int c = 0; c < 6; ++c) {
            cols[c] = table->column(QString::fromLatin1(names[c]));
            if (!cols[c] || cols[c]->isText)
                return makeError(
                    QStringLiteral("marks table '%1' needs numeric columns x, y, z, target_x, target_y, target_z")
                        .arg(context.inputPath(1)));
        }
        for (long long r = 0; r < table->rows(); ++r) {
            marks->first.emplace_back(cols[0]->numbers[size_t(r)], cols[1]->numbers[size_t(r)],
                                      cols[2]->numbers[size_t(r)]);
            marks->second.emplace_back(cols[3]->numbers[size_t(r)], cols[4]->numbers[size_t(r)],
                                       cols[5]->numbers[size_t(r)]);
        }
    }
    return marks;
}

}  // namespace

Status LpsAlignProcessor::prepare(const RunContext& context) const {
    auto marks = collectMarks(context);
    if (!marks) return marks.error();
    const bool full = context.text(QStringLiteral("mode")) == QLatin1String("full");
    if (marks->first.size() < (full ? 3u : 2u))
        return makeError(
            QStringLiteral("marks: mode=%1 needs at least %2 marks, got %3 (parameter marks or a marks table)")
                .arg(full ? "full" : "yaw")
                .arg(full ? 3 : 2)
                .arg(marks->first.size()));
    return {};
}

Expected<std::vector<ProcessorOutput>> LpsAlignProcessor::run(const RunContext& context) const {
    auto layout = loadBeacons(context, 0);
    if (!layout) return layout.error();
    auto marks = collectMarks(context);
    if (!marks) return marks.error();
    const AlignMode mode =
        context.text(QStringLiteral("mode")) == QLatin1String("full") ? AlignMode::Full : AlignMode::Yaw;
    auto transform = fitRigid(marks->first, marks->second, mode);
    if (!transform) return makeError(QStringLiteral("marks: %1").arg(transform.message()));
    Table table = tableFromLayout(transformLayout(*layout, *transform));
    double residual = 0.0;
    for (std::size_t k = 0; k < marks->first.size(); ++k)
        residual = std::max(residual, (transform->apply(marks->first[k]) - marks->second[k]).norm());
    table.attributes.insert(QStringLiteral("alignment_max_mark_error"), residual);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(table)});
    return outputs;
}

}  // namespace athlos::lps
