#include "ui/ItemDescription.h"

#include "core/model/Project.h"
#include "core/model/Table.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLocale>
#include <cmath>

namespace athlos::ui {

namespace {

QString esc(const QString& s) { return s.toHtmlEscaped(); }

QString row(const QString& label, const QString& valueHtml) {
    return QStringLiteral("<tr><td style='padding-right:10px; color:#555;'>%1</td><td>%2</td></tr>")
        .arg(esc(label), valueHtml);
}

QString jsonText(const QJsonObject& object) {
    return QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Indented)).trimmed();
}

QString number(double value) { return QLocale().toString(value, 'g', 10); }

// A small table's values (at most kValueCells cells): one row per table row, or, when the table has
// more columns than rows (a summary: gait-summary's 35 columns over 3 feet), one row per column.
constexpr long long kValueCells = 5000;

QString cellText(const TableColumn& c, long long r) {
    if (c.isText) return r < c.texts.size() ? esc(c.texts[qsizetype(r)]) : QString();
    if (r >= static_cast<long long>(c.numbers.size())) return {};
    const double v = c.numbers[std::size_t(r)];
    return std::isfinite(v) ? QLocale().toString(v, 'g', 5) : QString();
}

QString valuesHtml(const Table& table) {
    const long long rows = table.rows(), columns = static_cast<long long>(table.columns.size());
    if (rows == 0 || columns == 0 || rows * columns > kValueCells) return {};
    const auto header = [](const TableColumn& c) {
        return esc(c.unit.isEmpty() || c.unit == QLatin1String("1") ? c.name
                                                                    : QStringLiteral("%1 [%2]").arg(c.name, c.unit));
    };
    const QString cell = QStringLiteral("<td style='padding:1px 6px; text-align:right;'>%1</td>");
    QString html = QStringLiteral("<table style='border-collapse:collapse;'>");
    if (columns > rows) {
        for (const TableColumn& c : table.columns) {
            html += QStringLiteral("<tr><td style='padding-right:10px; color:#555;'>%1</td>").arg(header(c));
            for (long long r = 0; r < rows; ++r) html += cell.arg(cellText(c, r));
            html += QStringLiteral("</tr>");
        }
    } else {
        html += QStringLiteral("<tr>");
        for (const TableColumn& c : table.columns) html += QStringLiteral("<th>%1</th>").arg(header(c));
        html += QStringLiteral("</tr>");
        for (long long r = 0; r < rows; ++r) {
            html += QStringLiteral("<tr>");
            for (const TableColumn& c : table.columns) html += cell.arg(cellText(c, r));
            html += QStringLiteral("</tr>");
        }
    }
    return html + QStringLiteral("</table>");
}

}  // namespace

bool ItemDescription::isResult(const Provenance& provenance) {
    return !provenance.isEmpty() && !provenance.processorId.startsWith(QLatin1String("import:"));
}

QString ItemDescription::columnsText(const Columns& columns) {
    QStringList parts;
    for (const Column& c : columns)
        parts << (c.unit.isEmpty() ? c.name : QStringLiteral("%1 [%2]").arg(c.name, c.unit));
    return parts.join(QStringLiteral(", "));
}

QString ItemDescription::columnsText(const Table& table) {
    QStringList parts;
    for (const TableColumn& c : table.columns)
        parts << (c.isText           ? QStringLiteral("%1 (%2)").arg(c.name, tr("text"))
                  : c.unit.isEmpty() ? c.name
                                     : QStringLiteral("%1 [%2]").arg(c.name, c.unit));
    return parts.join(QStringLiteral(", "));
}

QString ItemDescription::projectHtml(const Project& project) {
    const ProjectMeta& meta = project.meta();
    QString html = QStringLiteral("<h3>%1</h3><table>").arg(esc(QFileInfo(project.path()).completeBaseName()));
    html += row(tr("File"), esc(QDir::toNativeSeparators(project.path())));
    if (!meta.sport.isEmpty()) html += row(tr("Sport"), esc(meta.sport));
    html += row(tr("Recordings"), QString::number(project.recordingNames().size()));
    html += row(tr("Streams"), QString::number(project.streamPaths().size()));
    if (!meta.created.isEmpty()) html += row(tr("Created"), esc(meta.created));
    if (!meta.modified.isEmpty()) html += row(tr("Modified"), esc(meta.modified));
    if (!meta.appVersion.isEmpty()) html += row(tr("Written by"), esc(QStringLiteral("Athlos ") + meta.appVersion));
    html += QStringLiteral("</table>");
    return html;
}

QString ItemDescription::recordingHtml(const Recording& recording) {
    QString html = QStringLiteral("<h3>%1</h3><table>").arg(esc(recording.name));
    html += row(tr("Streams"), QString::number(recording.streams.size()));
    html += row(tr("Tables"), QString::number(recording.tables.size()));
    html += row(tr("Annotations"), QString::number(recording.annotations.size()));
    html += QStringLiteral("</table>");
    if (!recording.metadata.isEmpty())
        html += QStringLiteral("<h4>%1</h4><pre>%2</pre>").arg(esc(tr("Metadata")), esc(jsonText(recording.metadata)));
    return html;
}

QString ItemDescription::streamHtml(const QString& path, const StreamInfo& info) {
    QString html = QStringLiteral("<h3>%1</h3><table>").arg(esc(path));
    html += row(tr("Kind"), esc(info.kind));
    if (!info.frame.isEmpty()) html += row(tr("Frame"), esc(info.frame));
    html += row(tr("Rows"), QLocale().toString(info.rows));
    if (info.rows > 0)
        html += row(tr("Time"), esc(tr("%1 s to %2 s (%3 s)")
                                        .arg(number(info.tBegin), number(info.tEnd), number(info.tEnd - info.tBegin))));
    QString columns = QStringLiteral("<table>");
    for (const Column& c : info.columns)
        columns += QStringLiteral("<tr><td>%1</td><td style='padding-left:8px; color:#555;'>%2</td></tr>")
                       .arg(esc(c.name), esc(c.unit));
    columns += QStringLiteral("</table>");
    html += row(tr("Columns"), columns);
    if (!info.contentHash.isEmpty())
        html += row(tr("Content hash"),
                    QStringLiteral("<code>%1</code>").arg(esc(QString::fromLatin1(info.contentHash.left(16)))));
    html += QStringLiteral("</table>");
    if (!info.attributes.isEmpty())
        html += QStringLiteral("<h4>%1</h4><pre>%2</pre>").arg(esc(tr("Attributes")), esc(jsonText(info.attributes)));
    if (!info.provenance.isEmpty()) html += provenanceHtml(info.provenance);
    return html;
}

QString ItemDescription::tableHtml(const QString& path, const Table& table) {
    QString html = QStringLiteral("<h3>%1</h3><table>").arg(esc(path));
    html += row(tr("Kind"), esc(table.kind));
    html += row(tr("Rows"), QLocale().toString(table.rows()));
    html += row(tr("Columns"), esc(columnsText(table)));
    html += QStringLiteral("</table>");
    if (const QString values = valuesHtml(table); !values.isEmpty())
        html += QStringLiteral("<h4>%1</h4>").arg(esc(tr("Values"))) + values;
    if (!table.attributes.isEmpty())
        html += QStringLiteral("<h4>%1</h4><pre>%2</pre>").arg(esc(tr("Attributes")), esc(jsonText(table.attributes)));
    if (!table.provenance.isEmpty()) html += provenanceHtml(table.provenance);
    return html;
}

QString ItemDescription::provenanceHtml(const Provenance& p) {
    QString html = QStringLiteral("<h4>%1</h4><table>").arg(esc(tr("Provenance")));
    if (isResult(p)) {
        html += row(tr("Processor"), esc(QStringLiteral("%1 %2").arg(p.processorId, p.processorVersion)));
    } else {
        html += row(tr("Imported with"), esc(p.processorId.section(QLatin1Char(':'), 1)));
    }
    if (!p.sourceFile.isEmpty()) html += row(tr("Source file"), esc(QDir::toNativeSeparators(p.sourceFile)));
    if (!p.inputs.empty()) {
        QString inputs;
        for (const ProvenanceInput& in : p.inputs)
            inputs += QStringLiteral("%1 <code style='color:#555;'>%2</code><br/>")
                          .arg(esc(in.name), esc(QString::fromLatin1(in.hash.left(12))));
        html += row(tr("Inputs"), inputs);
    }
    if (!p.appVersion.isEmpty()) html += row(tr("App version"), esc(p.appVersion));
    if (p.time.isValid()) html += row(tr("Time"), esc(p.time.toUTC().toString(Qt::ISODate)));
    html += QStringLiteral("</table>");
    if (!p.parameters.isEmpty())
        html += QStringLiteral("<b>%1</b><pre>%2</pre>").arg(esc(tr("Parameters")), esc(jsonText(p.parameters)));
    return html;
}

QString ItemDescription::streamToolTip(const QString& path, const StreamInfo& info) {
    QString text = tr("%1: %2, %3 rows").arg(path, info.kind, QLocale().toString(info.rows));
    text += QLatin1Char('\n') + columnsText(info.columns);
    const Provenance& p = info.provenance;
    if (isResult(p)) {
        QStringList inputs;
        for (const ProvenanceInput& in : p.inputs) inputs << in.name;
        text += QLatin1Char('\n') +
                tr("Result of %1 %2 from %3").arg(p.processorId, p.processorVersion, inputs.join(QStringLiteral(", ")));
        text += QLatin1Char('\n') +
                tr("Parameters: %1").arg(QString::fromUtf8(QJsonDocument(p.parameters).toJson(QJsonDocument::Compact)));
        text += QLatin1Char('\n') + tr("Athlos %1, %2").arg(p.appVersion, p.time.toUTC().toString(Qt::ISODate));
    } else if (!p.sourceFile.isEmpty()) {
        text += QLatin1Char('\n') + tr("Imported from %1").arg(QFileInfo(p.sourceFile).fileName());
    }
    return text;
}

QString ItemDescription::tableToolTip(const QString& path, const Table& table) {
    QString text = tr("%1: table %2, %3 rows").arg(path, table.kind, QLocale().toString(table.rows()));
    text += QLatin1Char('\n') + columnsText(table);
    const Provenance& p = table.provenance;
    if (isResult(p)) text += QLatin1Char('\n') + tr("Result of %1 %2").arg(p.processorId, p.processorVersion);
    return text;
}

}  // namespace athlos::ui
