#include "core/model/AnnotationEdit.h"

#include "core/model/Project.h"

#include <QJsonArray>

namespace athlos {

namespace {
const char* kindName(AnnotationEdit::Kind kind) {
    switch (kind) {
        case AnnotationEdit::Kind::Insert:
            return "insert";
        case AnnotationEdit::Kind::Remove:
            return "remove";
        case AnnotationEdit::Kind::Replace:
            return "replace";
        case AnnotationEdit::Kind::AddClass:
            return "add-class";
        case AnnotationEdit::Kind::ReplaceAll:
            return "replace-all";
    }
    return "";
}
}  // namespace

QJsonObject annotationToJson(const Annotation& a) {
    return {{QStringLiteral("label"), a.label},
            {QStringLiteral("t_start"), a.tStart},
            {QStringLiteral("t_end"), a.tEnd},
            {QStringLiteral("annotator"), a.annotator},
            {QStringLiteral("confidence"), a.confidence},
            {QStringLiteral("source"), a.source}};
}

Annotation annotationFromJson(const QJsonObject& json) {
    Annotation a;
    a.label = json.value(QStringLiteral("label")).toString();
    a.tStart = json.value(QStringLiteral("t_start")).toDouble();
    a.tEnd = json.value(QStringLiteral("t_end")).toDouble();
    a.annotator = json.value(QStringLiteral("annotator")).toString();
    a.confidence = json.value(QStringLiteral("confidence")).toDouble(1.0);
    a.source = json.value(QStringLiteral("source")).toString(QStringLiteral("manual"));
    return a;
}

AnnotationEdit AnnotationEdit::insert(QString recording, int index, Annotation annotation) {
    AnnotationEdit e;
    e.kind = Kind::Insert;
    e.recording = std::move(recording);
    e.index = index;
    e.after = std::move(annotation);
    return e;
}

AnnotationEdit AnnotationEdit::remove(QString recording, int index, Annotation annotation) {
    AnnotationEdit e;
    e.kind = Kind::Remove;
    e.recording = std::move(recording);
    e.index = index;
    e.before = std::move(annotation);
    return e;
}

AnnotationEdit AnnotationEdit::replace(QString recording, int index, Annotation before, Annotation after) {
    AnnotationEdit e;
    e.kind = Kind::Replace;
    e.recording = std::move(recording);
    e.index = index;
    e.before = std::move(before);
    e.after = std::move(after);
    return e;
}

AnnotationEdit AnnotationEdit::addClass(QString name) {
    AnnotationEdit e;
    e.kind = Kind::AddClass;
    e.className = std::move(name);
    return e;
}

AnnotationEdit AnnotationEdit::replaceAll(QString recording, Annotations before, Annotations after) {
    AnnotationEdit e;
    e.kind = Kind::ReplaceAll;
    e.recording = std::move(recording);
    e.beforeAll = std::move(before);
    e.afterAll = std::move(after);
    return e;
}

AnnotationEdit AnnotationEdit::inverse() const {
    AnnotationEdit e = *this;
    switch (kind) {
        case Kind::Insert:
            e.kind = Kind::Remove;
            e.before = after;
            e.after = {};
            break;
        case Kind::Remove:
            e.kind = Kind::Insert;
            e.after = before;
            e.before = {};
            break;
        case Kind::Replace:
            std::swap(e.before, e.after);
            break;
        case Kind::ReplaceAll:
            std::swap(e.beforeAll, e.afterAll);
            break;
        case Kind::AddClass:
            break;
    }
    return e;
}

Status AnnotationEdit::apply(Project& project) const {
    if (kind == Kind::AddClass) {
        if (className.isEmpty()) return makeError(QStringLiteral("annotation class without a name"));
        if (!project.annotationClasses().contains(className)) project.annotationClasses() << className;
        project.setModified(true);
        return {};
    }
    Recording* rec = project.recording(recording);
    if (!rec) return makeError(QStringLiteral("annotation edit for unknown recording '%1'").arg(recording));
    Annotations& list = rec->annotations;
    const int size = int(list.size());
    switch (kind) {
        case Kind::Insert:
            if (index < 0 || index > size)
                return makeError(QStringLiteral("annotation insert at %1 outside 0..%2 in '%3'")
                                     .arg(index)
                                     .arg(size)
                                     .arg(recording));
            list.insert(list.begin() + index, after);
            break;
        case Kind::Remove:
        case Kind::Replace:
            if (index < 0 || index >= size || !(list[std::size_t(index)] == before))
                return makeError(
                    QStringLiteral("annotation %1 of '%2' does not match the edit").arg(index).arg(recording));
            if (kind == Kind::Remove)
                list.erase(list.begin() + index);
            else
                list[std::size_t(index)] = after;
            break;
        case Kind::ReplaceAll:
            if (list != beforeAll)
                return makeError(QStringLiteral("the annotations of '%1' do not match the edit").arg(recording));
            list = afterAll;
            break;
        case Kind::AddClass:
            break;
    }
    project.setModified(true);
    return {};
}

QJsonObject AnnotationEdit::toJson() const {
    QJsonObject json{{QStringLiteral("op"), QString::fromLatin1(kindName(kind))}};
    if (kind == Kind::AddClass) {
        json[QStringLiteral("class")] = className;
        return json;
    }
    json[QStringLiteral("rec")] = recording;
    if (kind == Kind::ReplaceAll) {
        auto list = [](const Annotations& annotations) {
            QJsonArray array;
            for (const Annotation& a : annotations) array.append(annotationToJson(a));
            return array;
        };
        json[QStringLiteral("before")] = list(beforeAll);
        json[QStringLiteral("after")] = list(afterAll);
        return json;
    }
    json[QStringLiteral("index")] = index;
    if (kind != Kind::Insert) json[QStringLiteral("before")] = annotationToJson(before);
    if (kind != Kind::Remove) json[QStringLiteral("after")] = annotationToJson(after);
    return json;
}

Expected<AnnotationEdit> AnnotationEdit::fromJson(const QJsonObject& json) {
    const QString op = json.value(QStringLiteral("op")).toString();
    AnnotationEdit e;
    if (op == QLatin1String("insert"))
        e.kind = Kind::Insert;
    else if (op == QLatin1String("remove"))
        e.kind = Kind::Remove;
    else if (op == QLatin1String("replace"))
        e.kind = Kind::Replace;
    else if (op == QLatin1String("add-class"))
        e.kind = Kind::AddClass;
    else if (op == QLatin1String("replace-all"))
        e.kind = Kind::ReplaceAll;
    else
        return makeError(QStringLiteral("unknown annotation edit '%1'").arg(op));
    e.className = json.value(QStringLiteral("class")).toString();
    e.recording = json.value(QStringLiteral("rec")).toString();
    e.index = json.value(QStringLiteral("index")).toInt(-1);
    if (e.kind == Kind::ReplaceAll) {
        for (const auto& value : json.value(QStringLiteral("before")).toArray())
            e.beforeAll.push_back(annotationFromJson(value.toObject()));
        for (const auto& value : json.value(QStringLiteral("after")).toArray())
            e.afterAll.push_back(annotationFromJson(value.toObject()));
        return e;
    }
    if (json.contains(QStringLiteral("before")))
        e.before = annotationFromJson(json.value(QStringLiteral("before")).toObject());
    if (json.contains(QStringLiteral("after")))
        e.after = annotationFromJson(json.value(QStringLiteral("after")).toObject());
    return e;
}

}  // namespace athlos
