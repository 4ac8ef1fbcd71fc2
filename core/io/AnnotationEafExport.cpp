// ELAN Annotation Format export (exportAnnotationsEaf, declared in AnnotationIo.h).
//
// Written against the EAF 3.0 schema (http://www.mpi.nl/tools/elan/EAFv3.0.xsd; Max Planck Institute
// for Psycholinguistics, The Language Archive): ANNOTATION_DOCUMENT (DATE, AUTHOR, VERSION, FORMAT)
// holds in this order HEADER (TIME_UNITS="milliseconds", PROPERTY lastUsedAnnotationId), TIME_ORDER
// (TIME_SLOTs with TIME_VALUE in whole ms, xsd:unsignedInt, two per annotation), the TIERs with their
// ALIGNABLE_ANNOTATIONs (ANNOTATION_VALUE) and the LINGUISTIC_TYPE the tiers refer to.
//
// Tiers ↔ classes: one tier per label, named after it, so ELAN shows one row per class. ELAN does not
// allow overlapping annotations on one tier, so a label's overlapping annotations (e.g. of two
// annotators) go to further tiers "<label> (2)", …. A tier whose annotations share one annotator
// carries it in ANNOTATOR. Confidence and source have no place in EAF and are not written.
#include "core/io/AnnotationIo.h"

#include <QDateTime>
#include <QSaveFile>
#include <QSet>
#include <QXmlStreamWriter>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace athlos {
namespace {

struct Tier {
    QString id;
    qint64 lastEnd = 0;                    // ms
    std::vector<std::size_t> annotations;  // indices into the sorted list
};

}  // namespace

Status exportAnnotationsEaf(const Annotations& annotations, const QString& file) {
    // Whole milliseconds, as EAF stores them; ELAN's time axis starts at 0.
    Annotations sorted = annotations;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Annotation& a, const Annotation& b) {
        return a.tStart < b.tStart || (a.tStart == b.tStart && a.tEnd < b.tEnd);
    });
    std::vector<std::pair<qint64, qint64>> ms;
    for (const Annotation& a : sorted) {
        if (!std::isfinite(a.tStart) || !std::isfinite(a.tEnd) || a.tEnd < a.tStart)
            return makeError(QStringLiteral("%1: annotation '%2' has no valid interval (%3 … %4 s)")
                                 .arg(file, a.label)
                                 .arg(a.tStart)
                                 .arg(a.tEnd));
        if (a.tStart < 0.0)
            return makeError(QStringLiteral("%1: ELAN times are milliseconds from 0; annotation '%2' starts at %3 s")
                                 .arg(file, a.label)
                                 .arg(a.tStart));
        ms.emplace_back(std::llround(a.tStart * 1e3), std::llround(a.tEnd * 1e3));
    }

    // Tiers per label, in the order the labels first appear in time.
    std::vector<Tier> tiers;
    std::map<QString, std::vector<std::size_t>> tiersOfLabel;  // label → indices into tiers
    QSet<QString> tierIds;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        auto& own = tiersOfLabel[sorted[i].label];
        auto free =
            std::find_if(own.begin(), own.end(), [&](std::size_t t) { return tiers[t].lastEnd <= ms[i].first; });
        if (free == own.end()) {
            QString id = sorted[i].label;
            for (int n = int(own.size()) + 1; tierIds.contains(id); ++n)
                id = QStringLiteral("%1 (%2)").arg(sorted[i].label).arg(n);
            tierIds.insert(id);
            tiers.push_back({id, 0, {}});
            own.push_back(tiers.size() - 1);
            free = own.end() - 1;
        }
        tiers[*free].annotations.push_back(i);
        tiers[*free].lastEnd = ms[i].second;
    }

    // Two time slots per annotation, as ELAN writes them (a shared slot would tie the boundaries of
    // different annotations together when one is edited in ELAN), numbered in increasing time.
    std::vector<std::pair<qint64, std::size_t>> order;  // (ms, 2·annotation + end)
    for (std::size_t i = 0; i < ms.size(); ++i) {
        order.emplace_back(ms[i].first, 2 * i);
        order.emplace_back(ms[i].second, 2 * i + 1);
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<QString> slotOf(order.size());  // by 2·annotation + end
    for (std::size_t k = 0; k < order.size(); ++k) slotOf[order[k].second] = QStringLiteral("ts%1").arg(k + 1);

    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly))
        return makeError(QStringLiteral("%1: cannot write: %2").arg(file, out.errorString()));
    QXmlStreamWriter xml(&out);
    xml.setAutoFormatting(true);
    xml.setAutoFormattingIndent(4);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("ANNOTATION_DOCUMENT"));
    xml.writeAttribute(QStringLiteral("AUTHOR"), QString());
    xml.writeAttribute(QStringLiteral("DATE"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
    xml.writeAttribute(QStringLiteral("FORMAT"), QStringLiteral("3.0"));
    xml.writeAttribute(QStringLiteral("VERSION"), QStringLiteral("3.0"));
    xml.writeNamespace(QStringLiteral("http://www.w3.org/2001/XMLSchema-instance"), QStringLiteral("xsi"));
    xml.writeAttribute(QStringLiteral("http://www.w3.org/2001/XMLSchema-instance"),
                       QStringLiteral("noNamespaceSchemaLocation"),
                       QStringLiteral("http://www.mpi.nl/tools/elan/EAFv3.0.xsd"));

    xml.writeStartElement(QStringLiteral("HEADER"));
    xml.writeAttribute(QStringLiteral("MEDIA_FILE"), QString());
    xml.writeAttribute(QStringLiteral("TIME_UNITS"), QStringLiteral("milliseconds"));
    xml.writeStartElement(QStringLiteral("PROPERTY"));
    xml.writeAttribute(QStringLiteral("NAME"), QStringLiteral("lastUsedAnnotationId"));
    xml.writeCharacters(QString::number(sorted.size()));
    xml.writeEndElement();  // PROPERTY
    xml.writeEndElement();  // HEADER

    xml.writeStartElement(QStringLiteral("TIME_ORDER"));
    for (const auto& slot : order) {
        xml.writeEmptyElement(QStringLiteral("TIME_SLOT"));
        xml.writeAttribute(QStringLiteral("TIME_SLOT_ID"), slotOf[slot.second]);
        xml.writeAttribute(QStringLiteral("TIME_VALUE"), QString::number(slot.first));
    }
    xml.writeEndElement();  // TIME_ORDER

    const QString type = QStringLiteral("default-lt");
    for (const Tier& tier : tiers) {
        xml.writeStartElement(QStringLiteral("TIER"));
        xml.writeAttribute(QStringLiteral("LINGUISTIC_TYPE_REF"), type);
        xml.writeAttribute(QStringLiteral("TIER_ID"), tier.id);
        const QString& annotator = sorted[tier.annotations.front()].annotator;
        if (!annotator.isEmpty() && std::all_of(tier.annotations.begin(), tier.annotations.end(),
                                                [&](std::size_t i) { return sorted[i].annotator == annotator; }))
            xml.writeAttribute(QStringLiteral("ANNOTATOR"), annotator);
        for (std::size_t i : tier.annotations) {
            xml.writeStartElement(QStringLiteral("ANNOTATION"));
            xml.writeStartElement(QStringLiteral("ALIGNABLE_ANNOTATION"));
            xml.writeAttribute(QStringLiteral("ANNOTATION_ID"), QStringLiteral("a%1").arg(i + 1));
            xml.writeAttribute(QStringLiteral("TIME_SLOT_REF1"), slotOf[2 * i]);
            xml.writeAttribute(QStringLiteral("TIME_SLOT_REF2"), slotOf[2 * i + 1]);
            xml.writeTextElement(QStringLiteral("ANNOTATION_VALUE"), sorted[i].label);
            xml.writeEndElement();  // ALIGNABLE_ANNOTATION
            xml.writeEndElement();  // ANNOTATION
        }
        xml.writeEndElement();  // TIER
    }

    xml.writeEmptyElement(QStringLiteral("LINGUISTIC_TYPE"));
    xml.writeAttribute(QStringLiteral("GRAPHIC_REFERENCES"), QStringLiteral("false"));
    xml.writeAttribute(QStringLiteral("LINGUISTIC_TYPE_ID"), type);
    xml.writeAttribute(QStringLiteral("TIME_ALIGNABLE"), QStringLiteral("true"));
    xml.writeEndElement();  // ANNOTATION_DOCUMENT
    xml.writeEndDocument();
    if (xml.hasError() || !out.commit())
        return makeError(QStringLiteral("%1: cannot write: %2").arg(file, out.errorString()));
    return {};
}

}  // namespace athlos
