#pragma once
// An annotation edit on the undo stack: redo applies it, undo applies its inverse; both go
// through the editor, so both reach the project, the journal and the plots.
#include "core/model/AnnotationEdit.h"

#include <QUndoCommand>

namespace athlos::ui {

class AnnotationEditor;

class AnnotationCommand : public QUndoCommand {
public:
    AnnotationCommand(AnnotationEditor& editor, AnnotationEdit edit, const QString& text);
    void redo() override;
    void undo() override;
    const AnnotationEdit& edit() const { return edit_; }

private:
    AnnotationEditor& editor_;
    AnnotationEdit edit_;
};

}  // namespace athlos::ui
