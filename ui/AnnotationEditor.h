#pragma once
// The one way annotations change in the GUI: every create/edit/delete/accept is an undoable
// command, written to the crash journal before it is shown. Owns the undo stack (Ctrl+Z /
// Ctrl+Shift+Z) and the current class (keys 1–9) and annotator (Preferences, QSettings).
#include "core/model/AnnotationJournal.h"
#include "core/util/Expected.h"

#include <QObject>
#include <QString>
#include <map>
#include <QStringList>

class QUndoStack;

namespace athlos {
class Project;
}

namespace athlos::ui {

class AnnotationEditor : public QObject {
    Q_OBJECT

public:
    explicit AnnotationEditor(QObject* parent = nullptr);
    ~AnnotationEditor() override;

    // Clears the undo history and binds the journal to the project's file.
    void setProject(Project* project);
    Project* project() const { return project_; }
    QUndoStack* undoStack() const { return undoStack_; }
    AnnotationJournal& journal() { return journal_; }

    // Inserts in time order; returns the new index.
    Expected<int> create(const QString& recording, double tStart, double tEnd);
    Expected<int> create(const QString& recording, const Annotation& annotation);
    Status change(const QString& recording, int index, const Annotation& after);
    Status remove(const QString& recording, int index);
    // Review: a processor's annotation becomes a reviewed manual one (or is rejected = removed).
    Status accept(const QString& recording, int index);
    // Classes only grow; journaled but not undoable.
    Status addClass(const QString& name);

    QString currentClass() const;
    void setCurrentClass(const QString& name);
    // The class at 0-based position (keys 1–9), if there is one.
    bool selectClassByNumber(int number);

    static QString annotator();
    static void setAnnotator(const QString& name);

    // During a background save the project must not change: edits are refused meanwhile.
    void setLocked(bool locked) { locked_ = locked; }
    bool isLocked() const { return locked_; }

    // A processor replaced annotations of these recordings outside the editor. Each changed list is
    // journaled (as one "replace-all" edit against `before`, the lists before the run, whose
    // annotation state had digest baseDigest), so a crash before the next save loses nothing; the
    // undo steps refer to the old lists and are dropped, and the views redraw.
    void annotationsReplaced(const QStringList& recordings, const std::map<QString, Annotations>& before,
                             const QByteArray& baseDigest);

    // Applies edit to the project, journals it, tells the views. For AnnotationCommand.
    void perform(const AnnotationEdit& edit);

signals:
    void annotationsChanged(const QString& recording);
    void classesChanged();
    void currentClassChanged(const QString& name);
    void errorOccurred(const QString& message);

private:
    Status check(const QString& recording, int index) const;

    Project* project_ = nullptr;
    QUndoStack* undoStack_ = nullptr;
    AnnotationJournal journal_;
    QString currentClass_;
    bool locked_ = false;
};

}  // namespace athlos::ui
