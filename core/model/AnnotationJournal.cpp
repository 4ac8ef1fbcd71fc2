#include "core/model/AnnotationJournal.h"

#include "core/model/Project.h"

#include <QCryptographicHash>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace athlos {

bool AnnotationJournal::hasPendingEdits(const QString& projectPath) {
    const QFileInfo journal(pathFor(projectPath));
    if (!journal.exists() || journal.size() == 0) return false;
    const QFileInfo project(projectPath);
    return !project.exists() || journal.lastModified() >= project.lastModified();
}

namespace {

const QLatin1String kHeaderKey("journal");

}  // namespace

QByteArray AnnotationJournal::stateDigest(const Project& project) {
    // Canonical: recordings in name order (std::map), annotations in list order, compact JSON.
    QCryptographicHash hash(QCryptographicHash::Sha256);
    hash.addData(project.annotationClasses().join(QLatin1Char('\n')).toUtf8());
    for (const auto& [name, recording] : project.recordings()) {
        QJsonArray list;
        for (const Annotation& annotation : recording.annotations) list.append(annotationToJson(annotation));
        hash.addData(QByteArray("\n#") + name.toUtf8() + '\n');
        hash.addData(QJsonDocument(list).toJson(QJsonDocument::Compact));
    }
    return hash.result().toHex();
}

bool AnnotationJournal::belongsTo(const Project& project) {
    QFile file(pathFor(project.path()));
    if (!file.open(QIODevice::ReadOnly)) return true;
    const QJsonDocument first = QJsonDocument::fromJson(file.readLine());
    if (!first.isObject() || !first.object().contains(kHeaderKey)) return true;
    return first.object().value(QStringLiteral("base")).toString().toLatin1() == stateDigest(project);
}

Expected<std::vector<AnnotationEdit>> AnnotationJournal::read(const QString& journalPath) {
    QFile file(journalPath);
    if (!file.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: %2").arg(journalPath, file.errorString()));
    std::vector<AnnotationEdit> edits;
    int lineNumber = 0;
    while (!file.atEnd()) {
        const QByteArray line = file.readLine();
        ++lineNumber;
        const bool complete = line.endsWith('\n');
        if (line.trimmed().isEmpty()) continue;
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(line, &error);
        if (error.error != QJsonParseError::NoError || !doc.isObject()) {
            if (!complete) break;  // the write the crash interrupted
            return makeError(QStringLiteral("%1:%2: %3").arg(journalPath).arg(lineNumber).arg(error.errorString()));
        }
        if (doc.object().contains(kHeaderKey)) continue;  // the base digest
        auto edit = AnnotationEdit::fromJson(doc.object());
        if (!edit) return makeError(QStringLiteral("%1:%2: %3").arg(journalPath).arg(lineNumber).arg(edit.message()));
        edits.push_back(std::move(edit).value());
    }
    return edits;
}

Expected<int> AnnotationJournal::replay(Project& project) {
    const QString path = pathFor(project.path());
    auto edits = read(path);
    if (!edits) return edits.error();
    int applied = 0;
    for (const AnnotationEdit& edit : *edits) {
        const Status status = edit.apply(project);
        if (!status)
            return makeError(QStringLiteral("%1: edit %2: %3").arg(path).arg(applied + 1).arg(status.message()));
        ++applied;
    }
    return applied;
}

AnnotationJournal::AnnotationJournal(QString projectPath) {
    if (!projectPath.isEmpty()) setProjectPath(projectPath);
}

AnnotationJournal::~AnnotationJournal() = default;

void AnnotationJournal::setProjectPath(const QString& projectPath) {
    file_.close();
    file_.setFileName(pathFor(projectPath));
}

Status AnnotationJournal::append(const AnnotationEdit& edit, const Project* base) {
    return append(edit, base ? stateDigest(*base) : QByteArray());
}

Status AnnotationJournal::append(const AnnotationEdit& edit, const QByteArray& baseDigest) {
    if (file_.fileName().isEmpty()) return makeError(QStringLiteral("the annotation journal has no file"));
    if (!file_.isOpen() && !file_.open(QIODevice::WriteOnly | QIODevice::Append))
        return makeError(QStringLiteral("%1: %2").arg(file_.fileName(), file_.errorString()));
    QByteArray line;
    if (!baseDigest.isEmpty() && file_.size() == 0) {
        const QJsonObject header{{kHeaderKey, 1}, {QStringLiteral("base"), QString::fromLatin1(baseDigest)}};
        line = QJsonDocument(header).toJson(QJsonDocument::Compact) + '\n';
    }
    line += QJsonDocument(edit.toJson()).toJson(QJsonDocument::Compact);
    line += '\n';
    if (file_.write(line) != line.size() || !file_.flush())
        return makeError(QStringLiteral("%1: %2").arg(file_.fileName(), file_.errorString()));
#ifdef Q_OS_UNIX
    // flush() only reaches the OS; a power cut needs the bytes on the disk. One line is tiny.
    if (::fsync(file_.handle()) != 0) return makeError(QStringLiteral("%1: cannot sync to disk").arg(file_.fileName()));
#endif
    return {};
}

void AnnotationJournal::discard() {
    file_.close();
    if (!file_.fileName().isEmpty()) QFile::remove(file_.fileName());
}

}  // namespace athlos
