#include "core/io/AnnotationIo.h"

#include "core/io/CsvReader.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QXmlStreamReader>
#include <charconv>
#include <cmath>
#include <map>

namespace athlos {
namespace {

QString number(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return QString::fromLatin1(buf, r.ptr - buf);
}

QString csvText(const QString& text) {
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char(';')) &&
        !text.contains(QLatin1Char('\t')) && !text.contains(QLatin1Char('\n')) && !text.startsWith(QLatin1Char('#')) &&
        !text.startsWith(QLatin1Char(' ')) && !text.endsWith(QLatin1Char(' ')))
        return text;
    QString q = text;
    q.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

Status writeFile(const QString& file, const QByteArray& content) {
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly) || out.write(content) != content.size() || !out.commit())
        return makeError(QStringLiteral("%1: cannot write: %2").arg(file, out.errorString()));
    return {};
}

Status checkInterval(const Annotation& a, const QString& where) {
    if (!std::isfinite(a.tStart) || !std::isfinite(a.tEnd))
        return makeError(QStringLiteral("%1: start and end must be finite numbers").arg(where));
    if (a.tEnd < a.tStart)
        return makeError(
            QStringLiteral("%1: end %2 s is before start %3 s").arg(where, number(a.tEnd), number(a.tStart)));
    if (!(a.confidence >= 0.0 && a.confidence <= 1.0))
        return makeError(QStringLiteral("%1: confidence %2 is not in [0, 1]").arg(where, number(a.confidence)));
    if (a.label.trimmed().isEmpty()) return makeError(QStringLiteral("%1: empty label").arg(where));
    return {};
}

}  // namespace

Status exportAnnotationsCsv(const Annotations& annotations, const QString& file) {
    QString text = QStringLiteral("start,end,label,confidence,source,annotator\n");
    for (const Annotation& a : annotations)
        text += number(a.tStart) + QLatin1Char(',') + number(a.tEnd) + QLatin1Char(',') + csvText(a.label) +
                QLatin1Char(',') + number(a.confidence) + QLatin1Char(',') + csvText(a.source) + QLatin1Char(',') +
                csvText(a.annotator) + QLatin1Char('\n');
    return writeFile(file, text.toUtf8());
}

Status exportAnnotationsJson(const Annotations& annotations, const QString& file) {
    QJsonArray list;
    for (const Annotation& a : annotations)
        list.append(QJsonObject{{"start", a.tStart},
                                {"end", a.tEnd},
                                {"label", a.label},
                                {"confidence", a.confidence},
                                {"source", a.source},
                                {"annotator", a.annotator}});
    const QJsonObject root{{"format", "athlos-annotations"}, {"time_unit", "s"}, {"annotations", list}};
    return writeFile(file, QJsonDocument(root).toJson(QJsonDocument::Indented));
}

Status exportAnnotations(const Annotations& annotations, const QString& file) {
    const QString suffix = QFileInfo(file).suffix().toLower();
    if (suffix == QLatin1String("json")) return exportAnnotationsJson(annotations, file);
    if (suffix == QLatin1String("csv") || suffix == QLatin1String("txt"))
        return exportAnnotationsCsv(annotations, file);
    if (suffix == QLatin1String("eaf")) return exportAnnotationsEaf(annotations, file);
    return makeError(QStringLiteral("%1: annotations export to .csv, .json or .eaf (ELAN)").arg(file));
}

Expected<Annotations> readAnnotationsCsv(const QString& file) {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList header;
    if (!reader.readHeader(header))
        return makeError(
            QStringLiteral("%1: empty file (expected the header start,end,label[,confidence,source,annotator])")
                .arg(file));
    const long long headerLine = reader.line();
    for (QString& h : header) h = h.trimmed().toLower();
    static const QStringList kKnown{"start", "end", "label", "confidence", "source", "annotator"};
    for (qsizetype c = 0; c < header.size(); ++c)
        if (!kKnown.contains(header[c]))
            return makeError(QStringLiteral("%1:%2:%3: unknown column '%4' (columns: %5)")
                                 .arg(file)
                                 .arg(headerLine)
                                 .arg(c + 1)
                                 .arg(header[c], kKnown.join(QStringLiteral(", "))));
    for (const char* required : {"start", "end", "label"})
        if (!header.contains(QLatin1String(required)))
            return makeError(QStringLiteral("%1:%2: no column '%3' (start,end,label[,confidence,source,annotator])")
                                 .arg(file)
                                 .arg(headerLine)
                                 .arg(QLatin1String(required)));
    Annotations out;
    std::string cell;
    while (reader.nextRecord()) {
        Annotation a;
        a.source = QStringLiteral("import");
        a.annotator = QFileInfo(file).fileName();
        for (qsizetype c = 0; c < header.size(); ++c) {
            const QString& key = header[c];
            const QString at =
                QStringLiteral("%1:%2:%3 (column '%4')").arg(file).arg(reader.line()).arg(c + 1).arg(key);
            if (key == QLatin1String("start") || key == QLatin1String("end") || key == QLatin1String("confidence")) {
                double v = 0.0;
                const auto field = reader.number(v);
                if (field == CsvReader::Field::Missing)
                    return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                         .arg(file)
                                         .arg(reader.line())
                                         .arg(c + 1)
                                         .arg(reader.fieldsOnLine())
                                         .arg(header.size()));
                if (field == CsvReader::Field::Invalid)
                    return makeError(QStringLiteral("%1: '%2' is not a number")
                                         .arg(at, QString::fromUtf8(reader.lastField().data(),
                                                                    qsizetype(reader.lastField().size()))));
                if (field == CsvReader::Field::Empty) {
                    if (key != QLatin1String("confidence"))
                        return makeError(QStringLiteral("%1: empty %2").arg(at, key));
                    continue;
                }
                (key == QLatin1String("start") ? a.tStart : key == QLatin1String("end") ? a.tEnd : a.confidence) = v;
                continue;
            }
            if (!reader.text(cell))
                return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(c + 1)
                                     .arg(reader.fieldsOnLine())
                                     .arg(header.size()));
            const QString value = QString::fromUtf8(cell.data(), qsizetype(cell.size()));
            if (key == QLatin1String("label"))
                a.label = value;
            else if (key == QLatin1String("source") && !value.isEmpty())
                a.source = value;
            else if (key == QLatin1String("annotator") && !value.isEmpty())
                a.annotator = value;
        }
        if (!reader.finishRecord())
            return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                 .arg(file)
                                 .arg(reader.line())
                                 .arg(header.size() + 1)
                                 .arg(reader.fieldsOnLine())
                                 .arg(header.size()));
        if (Status s = checkInterval(a, QStringLiteral("%1:%2").arg(file).arg(reader.line())); !s) return s.error();
        out.push_back(a);
    }
    return out;
}

Expected<Annotations> readAnnotationsJson(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: cannot open: %2").arg(file, f.errorString()));
    const QByteArray bytes = f.readAll();
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError) {
        const int line = int(bytes.left(error.offset).count('\n')) + 1;
        const int column = int(error.offset - bytes.left(error.offset).lastIndexOf('\n'));
        return makeError(QStringLiteral("%1:%2:%3: %4").arg(file).arg(line).arg(column).arg(error.errorString()));
    }
    const QJsonArray list = doc.isArray() ? doc.array() : doc.object().value(QStringLiteral("annotations")).toArray();
    if (!doc.isArray() && !doc.object().value(QStringLiteral("annotations")).isArray())
        return makeError(QStringLiteral("%1: expected an object with an array \"annotations\"").arg(file));
    Annotations out;
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString where = QStringLiteral("%1: annotations[%2]").arg(file).arg(i);
        if (!list[i].isObject()) return makeError(QStringLiteral("%1: not an object").arg(where));
        const QJsonObject o = list[i].toObject();
        for (const char* key : {"start", "end"})
            if (!o.value(QLatin1String(key)).isDouble())
                return makeError(QStringLiteral("%1: \"%2\" must be a number (s)").arg(where, QLatin1String(key)));
        if (!o.value(QStringLiteral("label")).isString())
            return makeError(QStringLiteral("%1: \"label\" must be text").arg(where));
        Annotation a;
        a.tStart = o.value(QStringLiteral("start")).toDouble();
        a.tEnd = o.value(QStringLiteral("end")).toDouble();
        a.label = o.value(QStringLiteral("label")).toString();
        a.confidence = o.value(QStringLiteral("confidence")).toDouble(1.0);
        a.source = o.value(QStringLiteral("source")).toString(QStringLiteral("import"));
        a.annotator = o.value(QStringLiteral("annotator")).toString(QFileInfo(file).fileName());
        if (Status s = checkInterval(a, where); !s) return s.error();
        out.push_back(a);
    }
    return out;
}

Expected<Annotations> readAnnotationsEaf(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: cannot open: %2").arg(file, f.errorString()));
    QXmlStreamReader xml(&f);
    std::map<QString, double> timeSlots;  // TIME_SLOT_ID → s
    struct Pending {
        QString tier, ref1, ref2, value;
        qint64 line = 0;
    };
    std::vector<Pending> pending;
    QString tier;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        const auto attrs = xml.attributes();
        if (xml.name() == QLatin1String("TIME_SLOT")) {
            const QString id = attrs.value(QStringLiteral("TIME_SLOT_ID")).toString();
            if (attrs.hasAttribute(QStringLiteral("TIME_VALUE"))) {
                bool ok = false;
                const double ms = attrs.value(QStringLiteral("TIME_VALUE")).toDouble(&ok);
                if (!ok)
                    return makeError(QStringLiteral("%1:%2:%3: TIME_SLOT '%4': TIME_VALUE is not a number of ms")
                                         .arg(file)
                                         .arg(xml.lineNumber())
                                         .arg(xml.columnNumber())
                                         .arg(id));
                timeSlots[id] = ms * 1e-3;
            }
        } else if (xml.name() == QLatin1String("TIER")) {
            tier = attrs.value(QStringLiteral("TIER_ID")).toString();
        } else if (xml.name() == QLatin1String("ALIGNABLE_ANNOTATION")) {
            Pending p{tier,
                      attrs.value(QStringLiteral("TIME_SLOT_REF1")).toString(),
                      attrs.value(QStringLiteral("TIME_SLOT_REF2")).toString(),
                      {},
                      xml.lineNumber()};
            while (!xml.atEnd() && !(xml.isEndElement() && xml.name() == QLatin1String("ALIGNABLE_ANNOTATION"))) {
                xml.readNext();
                if (xml.isStartElement() && xml.name() == QLatin1String("ANNOTATION_VALUE"))
                    p.value = xml.readElementText().trimmed();
            }
            pending.push_back(p);
        }
    }
    if (xml.hasError())
        return makeError(QStringLiteral("%1:%2:%3: %4")
                             .arg(file)
                             .arg(xml.lineNumber())
                             .arg(xml.columnNumber())
                             .arg(xml.errorString()));
    Annotations out;
    for (const Pending& p : pending) {
        const auto a = timeSlots.find(p.ref1), b = timeSlots.find(p.ref2);
        if (a == timeSlots.end() || b == timeSlots.end())
            return makeError(QStringLiteral("%1:%2: annotation '%3' refers to a time slot without a time (%4, %5)")
                                 .arg(file)
                                 .arg(p.line)
                                 .arg(p.value, p.ref1, p.ref2));
        if (p.value.isEmpty()) continue;
        Annotation ann{p.value, a->second, b->second, p.tier, 1.0, QStringLiteral("import")};
        if (Status s = checkInterval(ann, QStringLiteral("%1:%2").arg(file).arg(p.line)); !s) return s.error();
        out.push_back(ann);
    }
    return out;
}

Annotations labelRuns(const std::vector<double>& t, const QStringList& labels, const QString& source,
                      const QString& annotator) {
    Annotations out;
    const size_t n = std::min(t.size(), size_t(labels.size()));
    size_t i = 0;
    while (i < n) {
        size_t j = i + 1;
        while (j < n && labels[qsizetype(j)] == labels[qsizetype(i)]) ++j;
        if (!labels[qsizetype(i)].isEmpty())
            out.push_back({labels[qsizetype(i)], t[i], j < n ? t[j] : t[n - 1], annotator, 1.0, source});
        i = j;
    }
    return out;
}

QString AnnotationImporter::description() const {
    return QStringLiteral("Annotations: CSV start,end,label[,confidence,source,annotator] (s), JSON, ELAN .eaf");
}

bool AnnotationImporter::canRead(const QString& file, const QByteArray& head) const {
    const QString suffix = QFileInfo(file).suffix().toLower();
    if (suffix == QLatin1String("eaf")) return true;
    const QByteArray start = head.trimmed().toLower();
    if (suffix == QLatin1String("json")) return start.startsWith('{') && head.contains("\"annotations\"");
    return suffix == QLatin1String("csv") && start.startsWith("start,end,label");
}

Expected<ImportResult> AnnotationImporter::read(const QString& file, const ImportOptions&, const Progress&) const {
    const QString suffix = QFileInfo(file).suffix().toLower();
    auto annotations = suffix == QLatin1String("eaf")    ? readAnnotationsEaf(file)
                       : suffix == QLatin1String("json") ? readAnnotationsJson(file)
                                                         : readAnnotationsCsv(file);
    if (!annotations) return annotations.error();
    if (annotations->empty()) return makeError(QStringLiteral("%1: no annotations").arg(file));
    ImportResult result;
    result.annotations[QString()] = std::move(*annotations);
    return result;
}

}  // namespace athlos
