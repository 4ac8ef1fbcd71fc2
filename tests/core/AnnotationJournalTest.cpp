// The crash journal of annotation edits: replay after a crash, and recognising a journal whose
// edits are already in the file (killed between the save's rename and the journal's removal).
#include "core/model/AnnotationEdit.h"
#include "core/model/AnnotationJournal.h"
#include "core/model/Project.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;

namespace {

std::unique_ptr<Project> savedProject(const QString& path) {
    auto project = Project::create(path, QStringLiteral("test"));
    project->recordings()[QStringLiteral("rec")].name = QStringLiteral("rec");
    project->annotationClasses() << QStringLiteral("tackle");
    EXPECT_TRUE(project->save());
    return project;
}

Annotation tackle(double t0) {
    Annotation a;
    a.label = QStringLiteral("tackle");
    a.tStart = t0;
    a.tEnd = t0 + 1.5;
    a.annotator = QStringLiteral("tester");
    return a;
}

// Journals an edit the way the editor does: journal first (with the base state), then apply.
void edit(Project& project, AnnotationJournal& journal, const AnnotationEdit& e) {
    ASSERT_TRUE(journal.append(e, &project));
    ASSERT_TRUE(e.apply(project));
}

}  // namespace

TEST(AnnotationJournal, ReplaysUnsavedEditsOntoTheSavedFile) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = savedProject(path);
    AnnotationJournal journal(path);
    edit(*project, journal, AnnotationEdit::insert(QStringLiteral("rec"), 0, tackle(1.0)));
    edit(*project, journal, AnnotationEdit::insert(QStringLiteral("rec"), 1, tackle(4.0)));
    edit(*project, journal, AnnotationEdit::replace(QStringLiteral("rec"), 0, tackle(1.0), tackle(2.0)));
    const Annotations expected = project->recording(QStringLiteral("rec"))->annotations;

    // "Crash": the project is not saved; reopen from disk.
    auto reopened = Project::open(path);
    ASSERT_TRUE(reopened);
    EXPECT_TRUE(AnnotationJournal::hasPendingEdits(path));
    EXPECT_TRUE(AnnotationJournal::belongsTo(**reopened));
    auto applied = AnnotationJournal::replay(**reopened);
    ASSERT_TRUE(applied) << applied.message().toStdString();
    EXPECT_EQ(*applied, 3);
    EXPECT_EQ((*reopened)->recording(QStringLiteral("rec"))->annotations, expected);
}

TEST(AnnotationJournal, RecognisesAJournalWhoseEditsWereSaved) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = savedProject(path);
    AnnotationJournal journal(path);
    edit(*project, journal, AnnotationEdit::insert(QStringLiteral("rec"), 0, tackle(1.0)));
    edit(*project, journal, AnnotationEdit::insert(QStringLiteral("rec"), 1, tackle(4.0)));
    // Saved, then killed before journal.discard(); the journal's time stamp is not older than the
    // file's, so the time test alone would replay the edits a second time.
    ASSERT_TRUE(project->save());
    QFile journalFile(AnnotationJournal::pathFor(path));
    ASSERT_TRUE(journalFile.open(QIODevice::ReadWrite));
    ASSERT_TRUE(journalFile.setFileTime(QFileInfo(path).lastModified().addSecs(1), QFileDevice::FileModificationTime));
    journalFile.close();

    auto reopened = Project::open(path);
    ASSERT_TRUE(reopened);
    EXPECT_TRUE(AnnotationJournal::hasPendingEdits(path));
    EXPECT_FALSE(AnnotationJournal::belongsTo(**reopened));
    EXPECT_EQ((*reopened)->recording(QStringLiteral("rec"))->annotations.size(), 2u);
}

TEST(AnnotationJournal, JournalWithoutDigestStillReplays) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = savedProject(path);
    AnnotationJournal journal(path);
    const AnnotationEdit e = AnnotationEdit::insert(QStringLiteral("rec"), 0, tackle(1.0));
    ASSERT_TRUE(journal.append(e));  // no base: a journal written by an older version
    auto reopened = Project::open(path);
    ASSERT_TRUE(reopened);
    EXPECT_TRUE(AnnotationJournal::belongsTo(**reopened));
    auto edits = AnnotationJournal::read(AnnotationJournal::pathFor(path));
    ASSERT_TRUE(edits);
    ASSERT_EQ(edits->size(), 1u);
    EXPECT_EQ(edits->front(), e);
}

TEST(AnnotationJournal, DigestChangesWithAnyAnnotationField) {
    QTemporaryDir dir;
    auto project = savedProject(dir.filePath(QStringLiteral("p.athlos")));
    const QByteArray empty = AnnotationJournal::stateDigest(*project);
    ASSERT_TRUE(AnnotationEdit::insert(QStringLiteral("rec"), 0, tackle(1.0)).apply(*project));
    const QByteArray one = AnnotationJournal::stateDigest(*project);
    EXPECT_NE(one, empty);
    Annotation moved = tackle(1.0);
    moved.confidence = 0.5;
    ASSERT_TRUE(AnnotationEdit::replace(QStringLiteral("rec"), 0, tackle(1.0), moved).apply(*project));
    EXPECT_NE(AnnotationJournal::stateDigest(*project), one);
    project->annotationClasses() << QStringLiteral("scrum");
    EXPECT_NE(AnnotationJournal::stateDigest(*project), one);
}
