#include "ui/AnnotationEditor.h"

#include "core/model/Project.h"
#include "ui/AnnotationCommand.h"

#include <QSettings>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace athlos::ui {

namespace {
const QString kAnnotatorKey = QStringLiteral("annotation/annotator");
}

AnnotationEditor::AnnotationEditor(QObject* parent) : QObject(parent), undoStack_(new QUndoStack(this)) {}

AnnotationEditor::~AnnotationEditor() = default;

void AnnotationEditor::setProject(Project* project) {
    undoStack_->clear();
    project_ = project;
    journal_.setProjectPath(project ? project->path() : QString());
    const QStringList classes = project ? project->annotationClasses() : QStringList();
    setCurrentClass(classes.contains(currentClass_) ? currentClass_ : classes.value(0));
    emit classesChanged();
}

QString AnnotationEditor::annotator() {
    const QString stored = QSettings().value(kAnnotatorKey).toString();
    if (!stored.isEmpty()) return stored;
    const QString user = qEnvironmentVariable("USER", qEnvironmentVariable("USERNAME"));
    return user.isEmpty() ? QStringLiteral("annotator") : user;
}

void AnnotationEditor::setAnnotator(const QString& name) { QSettings().setValue(kAnnotatorKey, name.trimmed()); }

QString AnnotationEditor::currentClass() const { return currentClass_; }

void AnnotationEditor::setCurrentClass(const QString& name) {
    if (name == currentClass_) return;
    currentClass_ = name;
    emit currentClassChanged(name);
}

bool AnnotationEditor::selectClassByNumber(int number) {
    if (!project_ || number < 0 || number >= project_->annotationClasses().size()) return false;
    setCurrentClass(project_->annotationClasses().at(number));
    return true;
}

Status AnnotationEditor::check(const QString& recording, int index) const {
    if (!project_) return makeError(tr("Open a project first."));
    if (locked_) return makeError(tr("The project is being saved; try again in a moment."));
    const Recording* rec = project_->recording(recording);
    if (!rec) return makeError(tr("No recording '%1'.").arg(recording));
    if (index != -1 && (index < 0 || index >= int(rec->annotations.size())))
        return makeError(tr("No annotation %1 in '%2'.").arg(index).arg(recording));
    return {};
}

Expected<int> AnnotationEditor::create(const QString& recording, double tStart, double tEnd) {
    Annotation a;
    a.label = currentClass_;
    a.tStart = std::min(tStart, tEnd);
    a.tEnd = std::max(tStart, tEnd);
    a.annotator = annotator();
    a.source = QStringLiteral("manual");
    return create(recording, a);
}

Expected<int> AnnotationEditor::create(const QString& recording, const Annotation& annotation) {
    if (Status s = check(recording, -1); !s) return s.error();
    if (annotation.label.isEmpty()) return makeError(tr("Choose or add an annotation class first."));
    if (!std::isfinite(annotation.tStart) || !std::isfinite(annotation.tEnd) || annotation.tEnd < annotation.tStart)
        return makeError(tr("An annotation needs a start before its end."));
    const Annotations& list = project_->recording(recording)->annotations;
    // Kept sorted by start, so review and the table read in time order.
    const auto at = std::upper_bound(list.begin(), list.end(), annotation.tStart,
                                     [](double t, const Annotation& a) { return t < a.tStart; });
    const int index = int(at - list.begin());
    undoStack_->push(new AnnotationCommand(*this, AnnotationEdit::insert(recording, index, annotation),
                                           tr("Create %1").arg(annotation.label)));
    return index;
}

Status AnnotationEditor::change(const QString& recording, int index, const Annotation& after) {
    if (Status s = check(recording, index); !s) return s;
    if (!(after.tEnd >= after.tStart)) return makeError(tr("An annotation needs a start before its end."));
    const Annotation before = project_->recording(recording)->annotations[std::size_t(index)];
    if (before == after) return {};
    undoStack_->push(new AnnotationCommand(*this, AnnotationEdit::replace(recording, index, before, after),
                                           tr("Edit %1").arg(after.label)));
    return {};
}

Status AnnotationEditor::remove(const QString& recording, int index) {
    if (Status s = check(recording, index); !s) return s;
    const Annotation before = project_->recording(recording)->annotations[std::size_t(index)];
    undoStack_->push(new AnnotationCommand(*this, AnnotationEdit::remove(recording, index, before),
                                           tr("Delete %1").arg(before.label)));
    return {};
}

Status AnnotationEditor::accept(const QString& recording, int index) {
    if (Status s = check(recording, index); !s) return s;
    Annotation after = project_->recording(recording)->annotations[std::size_t(index)];
    after.source = QStringLiteral("manual");
    after.annotator = annotator();
    return change(recording, index, after);
}

Status AnnotationEditor::addClass(const QString& name) {
    const QString trimmed = name.trimmed();
    if (!project_) return makeError(tr("Open a project first."));
    if (trimmed.isEmpty()) return makeError(tr("A class needs a name."));
    if (project_->annotationClasses().contains(trimmed)) return {};
    const AnnotationEdit edit = AnnotationEdit::addClass(trimmed);
    if (Status journaled = journal_.append(edit, project_); !journaled) return journaled;
    if (Status applied = edit.apply(*project_); !applied) return applied;
    if (currentClass_.isEmpty()) setCurrentClass(trimmed);
    emit classesChanged();
    return {};
}

void AnnotationEditor::annotationsReplaced(const QStringList& recordings, const std::map<QString, Annotations>& before,
                                           const QByteArray& baseDigest) {
    undoStack_->clear();
    for (const QString& recording : recordings) {
        const Recording* rec = project_ ? project_->recording(recording) : nullptr;
        const auto old = before.find(recording);
        const Annotations previous = old == before.end() ? Annotations{} : old->second;
        if (rec && rec->annotations != previous) {
            const AnnotationEdit edit = AnnotationEdit::replaceAll(recording, previous, rec->annotations);
            if (Status journaled = journal_.append(edit, baseDigest); !journaled)
                emit errorOccurred(journaled.message());
        }
        emit annotationsChanged(recording);
    }
}

void AnnotationEditor::perform(const AnnotationEdit& edit) {
    if (!project_) return;
    // Journal first: what the user sees must survive a crash right after.
    if (Status journaled = journal_.append(edit, project_); !journaled) emit errorOccurred(journaled.message());
    if (Status applied = edit.apply(*project_); !applied) {
        emit errorOccurred(applied.message());
        return;
    }
    emit annotationsChanged(edit.recording);
}

}  // namespace athlos::ui
