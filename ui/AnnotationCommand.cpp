#include "ui/AnnotationCommand.h"

#include "ui/AnnotationEditor.h"

namespace athlos::ui {

AnnotationCommand::AnnotationCommand(AnnotationEditor& editor, AnnotationEdit edit, const QString& text)
    : QUndoCommand(text), editor_(editor), edit_(std::move(edit)) {}

void AnnotationCommand::redo() { editor_.perform(edit_); }

void AnnotationCommand::undo() { editor_.perform(edit_.inverse()); }

}  // namespace athlos::ui
