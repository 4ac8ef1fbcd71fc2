#pragma once
// One change to a recording's annotations: the unit of undo in the GUI and of the crash journal.
// Edits carry the "before" state, so they can be inverted and checked when replayed.
#include "core/model/Annotation.h"
#include "core/util/Expected.h"

#include <QJsonObject>
#include <QString>

namespace athlos {

class Project;

struct AnnotationEdit {
    // ReplaceAll: a recording's whole list at once (what a processor run that writes predicted
    // annotations changes), journaled like a manual edit.
    enum class Kind { Insert, Remove, Replace, AddClass, ReplaceAll };

    Kind kind = Kind::Insert;
    QString recording;
    int index = -1;                   // position in Recording::annotations
    Annotation before;                // Remove, Replace
    Annotation after;                 // Insert, Replace
    QString className;                // AddClass
    Annotations beforeAll, afterAll;  // ReplaceAll

    static AnnotationEdit insert(QString recording, int index, Annotation annotation);
    static AnnotationEdit remove(QString recording, int index, Annotation annotation);
    static AnnotationEdit replace(QString recording, int index, Annotation before, Annotation after);
    static AnnotationEdit addClass(QString name);
    static AnnotationEdit replaceAll(QString recording, Annotations before, Annotations after);

    // Insert ↔ Remove, Replace swaps before/after. AddClass has no inverse (classes only grow).
    AnnotationEdit inverse() const;
    // Applies to project; refuses (and changes nothing) when the project does not match the
    // edit's "before" state, e.g. a journal that belongs to another version of the file.
    Status apply(Project& project) const;

    QJsonObject toJson() const;
    static Expected<AnnotationEdit> fromJson(const QJsonObject& json);
    bool operator==(const AnnotationEdit&) const = default;
};

QJsonObject annotationToJson(const Annotation& annotation);
Annotation annotationFromJson(const QJsonObject& json);

}  // namespace athlos
