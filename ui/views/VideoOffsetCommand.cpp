#include "ui/views/VideoOffsetCommand.h"

namespace athlos::ui {

VideoOffsetCommand::VideoOffsetCommand(std::function<void(double)> apply, double before, double after,
                                       const QString& text)
    : QUndoCommand(text), apply_(std::move(apply)), before_(before), after_(after) {}

void VideoOffsetCommand::undo() { apply_(before_); }

void VideoOffsetCommand::redo() { apply_(after_); }

}  // namespace athlos::ui
