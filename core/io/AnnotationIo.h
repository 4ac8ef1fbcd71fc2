#pragma once
// Annotations as files: CSV `start,end,label,confidence,source,annotator` (times in s, one row per
// annotation; confidence, source and annotator optional on import), JSON {"annotations": [{"start",
// "end", "label", "confidence", "source", "annotator"}]}, and ELAN .eaf (read: every tier's
// time-aligned annotations, the tier name as annotator; write: EAF 3.0, one tier per label, times in
// whole ms, see AnnotationEafExport.cpp). Errors name the file and line (and column) or the JSON entry.
//
// labelRuns() turns a per-sample label column into intervals: runs of equal labels, each from its
// first sample to the first sample of the next run (the last run to the last sample); an empty
// label is no annotation.
#include "core/io/Importer.h"
#include "core/model/Annotation.h"
#include "core/util/Expected.h"

#include <QString>
#include <vector>

namespace athlos {

Status exportAnnotationsCsv(const Annotations& annotations, const QString& file);
Status exportAnnotationsJson(const Annotations& annotations, const QString& file);
// ELAN Annotation Format 3.0; refuses negative times (ELAN's axis starts at 0).
Status exportAnnotationsEaf(const Annotations& annotations, const QString& file);
// By extension: .csv/.txt, .json, .eaf.
Status exportAnnotations(const Annotations& annotations, const QString& file);

Expected<Annotations> readAnnotationsCsv(const QString& file);
Expected<Annotations> readAnnotationsJson(const QString& file);
Expected<Annotations> readAnnotationsEaf(const QString& file);

// Runs of equal labels (labels[i] belongs to t[i]; "" = none) → annotations with source, annotator.
Annotations labelRuns(const std::vector<double>& t, const QStringList& labels, const QString& source,
                      const QString& annotator);

// Imports annotation files (--format annotations; detected from a CSV header start,end,label, a JSON
// object with "annotations", or an .eaf file) onto the target recording.
class AnnotationImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("annotations"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv", "json", "eaf"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

}  // namespace athlos
