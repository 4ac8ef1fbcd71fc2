// Labels and annotations as files: a per-sample label column (numbers or text) becomes annotation
// intervals; annotations export to CSV and JSON and import back (also from ELAN .eaf) with errors
// that name the file, line and column.
#include "TestFiles.h"
#include "core/io/AnnotationIo.h"
#include "core/io/Importer.h"

#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos;

namespace {

class Labels : public ::testing::Test {
protected:
    Expected<ImportResult> import(const QByteArray& content, const QString& name = QStringLiteral("walk.csv")) {
        ImportOptions o = options;
        o.format = QStringLiteral("csv");
        o.kind = QStringLiteral("imu");
        o.target = QStringLiteral("rec");
        o.labelColumn = QStringLiteral("label");
        return importFile(test::writeFile(dir_, name, content), o);
    }
    QString write(const QString& name, const QByteArray& content) { return test::writeFile(dir_, name, content); }
    QString path(const QString& name) const { return dir_.filePath(name); }
    ImportOptions options;

private:
    QTemporaryDir dir_;
};

Annotation ann(const char* label, double a, double b, const char* annotator = "walk.csv") {
    return {QString::fromUtf8(label), a, b, QString::fromUtf8(annotator), 1.0, QStringLiteral("import")};
}

}  // namespace

TEST_F(Labels, TextLabelsBecomeRunsNotAColumn) {
    const auto r = import("t,acc_x,label\n0,1,walk\n0.1,1,walk\n0.2,1,\n0.3,1,run\n0.4,1,run\n0.5,1,walk\n");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = std::get<Stream>(r->items.at(0).item);
    EXPECT_EQ(s.info().columns.size(), 1u);  // acc_x only
    ASSERT_EQ(r->annotations.count("rec"), 1u);
    EXPECT_EQ(r->annotations.at("rec"),
              (Annotations{ann("walk", 0, 0.2), ann("run", 0.3, 0.5), ann("walk", 0.5, 0.5)}));

    auto project = Project::create(path("p.athlos"));
    ASSERT_TRUE(applyImport(*project, *r, false).ok());
    EXPECT_EQ(project->recording("rec")->annotations.size(), 3u);
    // Importing the same file again: refused, or replaced with overwrite.
    ImportResult onlyAnnotations;
    onlyAnnotations.annotations = r->annotations;
    const Status again = applyImport(*project, onlyAnnotations, false);
    ASSERT_FALSE(again.ok());
    EXPECT_TRUE(again.message().contains("already has annotations from walk.csv")) << qPrintable(again.message());
    ASSERT_TRUE(applyImport(*project, onlyAnnotations, true).ok());
    EXPECT_EQ(project->recording("rec")->annotations.size(), 3u);
}

TEST_F(Labels, NumberLabelsWithNamesFollowTheTimeRepair) {
    options.labelNames = {{"0", "rest"}, {"1", "run"}};
    options.timeRepair = QStringLiteral("sort");
    const auto r = import("t,acc_x,label\n0.2,1,1.0\n0,1,0\n0.1,1,0\n0.3,1,1\n");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(r->annotations.at("rec"), (Annotations{ann("rest", 0, 0.2), ann("run", 0.2, 0.3)}));
    const auto bad = import("t,acc_x,label\n0,1,0\n0.1,1,7\n");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(
        "walk.csv:3:3 (column 'label'): label '7' has no name in the label names (0=rest, 1=run)"))
        << qPrintable(bad.message());
}

TEST_F(Labels, LabelColumnErrors) {
    options.labelColumn = QStringLiteral("activity");
    ImportOptions o = options;
    o.format = QStringLiteral("csv");
    o.kind = QStringLiteral("imu");
    o.target = QStringLiteral("rec");
    const auto r = importFile(write("x.csv", "t,acc_x\n0,1\n"), o);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("x.csv:1: label column 'activity' is not in the file")) << qPrintable(r.message());
}

TEST_F(Labels, AnnotationFilesRoundTrip) {
    const Annotations list{ann("sprint, fast", 1.5, 3.25, "coach"), {"jump", 4, 4, "model", 0.75, "gait-events"}};
    ASSERT_TRUE(exportAnnotations(list, path("a.csv")).ok());
    ASSERT_TRUE(exportAnnotations(list, path("a.json")).ok());
    QFile csv(path("a.csv"));
    ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
    EXPECT_EQ(csv.readAll(),
              QByteArray("start,end,label,confidence,source,annotator\n1.5,3.25,\"sprint, fast\",1,import,coach\n"
                         "4,4,jump,0.75,gait-events,model\n"));
    EXPECT_EQ(*readAnnotationsCsv(path("a.csv")), list);
    EXPECT_EQ(*readAnnotationsJson(path("a.json")), list);
    // Imported onto a recording, auto-detected.
    ImportOptions o;
    o.target = QStringLiteral("trial");
    for (const char* file : {"a.csv", "a.json"}) {
        const auto r = importFile(path(file), o);
        ASSERT_TRUE(r.ok()) << file << ": " << qPrintable(r.message());
        EXPECT_TRUE(r->items.empty());
        EXPECT_EQ(r->annotations.at("trial"), list);
    }
    EXPECT_FALSE(exportAnnotations(list, path("a.h5")).ok());
}

TEST_F(Labels, AnnotationFileErrors) {
    auto r = readAnnotationsCsv(write("b.csv", "start,end,label\n0,1,walk\n2,abc,run\n"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), path("b.csv") + QStringLiteral(":3:2 (column 'end'): 'abc' is not a number"));
    r = readAnnotationsCsv(write("c.csv", "start,end,label\n2,1,walk\n"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().endsWith("c.csv:2: end 1 s is before start 2 s")) << qPrintable(r.message());
    r = readAnnotationsCsv(write("d.csv", "start,stop,label\n0,1,walk\n"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().endsWith(
        "d.csv:1:2: unknown column 'stop' (columns: start, end, label, confidence, source, annotator)"))
        << qPrintable(r.message());
    r = readAnnotationsJson(
        write("e.json", "{\"annotations\": [{\"start\": 0, \"end\": 1, \"label\": \"a\"}, {\"start\": \"x\"}]}"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().endsWith("e.json: annotations[1]: \"start\" must be a number (s)"))
        << qPrintable(r.message());
    r = readAnnotationsJson(write("f.json", "{\"annotations\": [\n{\"start\": 0,,}]}"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("f.json:2:")) << qPrintable(r.message());
}

TEST_F(Labels, ElanEaf) {
    const QString eaf = write("s.eaf", R"(<?xml version="1.0" encoding="UTF-8"?>
<ANNOTATION_DOCUMENT AUTHOR="" DATE="2024-05-01T10:00:00+00:00" FORMAT="3.0" VERSION="3.0">
  <HEADER MEDIA_FILE="" TIME_UNITS="milliseconds"/>
  <TIME_ORDER>
    <TIME_SLOT TIME_SLOT_ID="ts1" TIME_VALUE="1500"/>
    <TIME_SLOT TIME_SLOT_ID="ts2" TIME_VALUE="3250"/>
  </TIME_ORDER>
  <TIER LINGUISTIC_TYPE_REF="default" TIER_ID="coach">
    <ANNOTATION>
      <ALIGNABLE_ANNOTATION ANNOTATION_ID="a1" TIME_SLOT_REF1="ts1" TIME_SLOT_REF2="ts2">
        <ANNOTATION_VALUE>sprint</ANNOTATION_VALUE>
      </ALIGNABLE_ANNOTATION>
    </ANNOTATION>
  </TIER>
</ANNOTATION_DOCUMENT>
)");
    const auto r = readAnnotationsEaf(eaf);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(*r, (Annotations{ann("sprint", 1.5, 3.25, "coach")}));
    const auto broken = readAnnotationsEaf(write("t.eaf", "<ANNOTATION_DOCUMENT>\n<TIER>\n</ANNOTATION_DOCUMENT>\n"));
    ASSERT_FALSE(broken.ok());
    EXPECT_TRUE(broken.message().contains("t.eaf:3:")) << qPrintable(broken.message());
}

// ELAN export (issue #13 item 7): EAF 3.0 with one tier per label; read back by the ELAN import the
// intervals and labels are the same to 1 ms. Overlapping annotations of one label go to a second
// tier (ELAN forbids overlaps on a tier); negative times are refused.
TEST_F(Labels, ElanEafExportRoundTrip) {
    const Annotations list{ann("sprint", 1.5, 3.2504, "coach"),
                           ann("walk", 0.0, 1.5, "coach"),
                           {"jump", 4.0, 4.0, "model", 0.75, "gait-events"},
                           ann("walk", 5.1234, 9.0, "coach"),
                           ann("walk", 6.0, 7.0, "analyst"),
                           ann("sprint, fast <&>", 10.0, 12.5, "coach")};
    ASSERT_TRUE(exportAnnotations(list, path("a.eaf")).ok());
    QFile file(path("a.eaf"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray xml = file.readAll();
    for (const char* part :
         {"<ANNOTATION_DOCUMENT AUTHOR=\"\" DATE=\"", "FORMAT=\"3.0\" VERSION=\"3.0\"",
          "xsi:noNamespaceSchemaLocation=\"http://www.mpi.nl/tools/elan/EAFv3.0.xsd\"",
          "<HEADER MEDIA_FILE=\"\" TIME_UNITS=\"milliseconds\">", "<TIME_SLOT TIME_SLOT_ID=\"ts1\" TIME_VALUE=\"0\"/>",
          "<TIER LINGUISTIC_TYPE_REF=\"default-lt\" TIER_ID=\"walk\" ANNOTATOR=\"coach\">",
          "<TIER LINGUISTIC_TYPE_REF=\"default-lt\" TIER_ID=\"walk (2)\" ANNOTATOR=\"analyst\">",
          "<ANNOTATION_VALUE>sprint, fast &lt;&amp;&gt;</ANNOTATION_VALUE>",
          "<LINGUISTIC_TYPE GRAPHIC_REFERENCES=\"false\" LINGUISTIC_TYPE_ID=\"default-lt\" TIME_ALIGNABLE=\"true\"/>"})
        EXPECT_TRUE(xml.contains(part)) << part << "\n" << xml.toStdString();
    EXPECT_LT(xml.indexOf("</TIME_ORDER>"), xml.indexOf("<TIER "));          // schema order: HEADER, TIME_ORDER,
    EXPECT_LT(xml.lastIndexOf("</TIER>"), xml.indexOf("<LINGUISTIC_TYPE"));  // TIER*, LINGUISTIC_TYPE*

    auto back = readAnnotationsEaf(path("a.eaf"));
    ASSERT_TRUE(back.ok()) << qPrintable(back.message());
    ASSERT_EQ(back->size(), list.size());
    for (const Annotation& a : list) {
        const auto same = std::count_if(back->begin(), back->end(), [&](const Annotation& b) {
            return b.label == a.label && std::abs(b.tStart - a.tStart) <= 0.5e-3 && std::abs(b.tEnd - a.tEnd) <= 0.5e-3;
        });
        EXPECT_EQ(same, 1) << a.label.toStdString() << " " << a.tStart;
    }
    // The tiers are the classes: the tier name comes back as the annotator.
    for (const Annotation& b : *back) EXPECT_TRUE(b.annotator.startsWith(b.label)) << b.annotator.toStdString();

    const auto negative = exportAnnotations({ann("walk", -0.5, 1.0)}, path("n.eaf"));
    ASSERT_FALSE(negative.ok());
    EXPECT_TRUE(
        negative.message().endsWith("n.eaf: ELAN times are milliseconds from 0; annotation 'walk' starts at -0.5 s"))
        << qPrintable(negative.message());
    EXPECT_FALSE(QFile::exists(path("n.eaf")));
}
