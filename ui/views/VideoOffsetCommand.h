#pragma once
// A change of a video's offset, on the video dock's undo stack: undo and redo hand the old or the
// new offset to the dock, which stores it in the project.
#include <QString>
#include <QUndoCommand>
#include <functional>

namespace athlos::ui {

class VideoOffsetCommand : public QUndoCommand {
public:
    VideoOffsetCommand(std::function<void(double)> apply, double before, double after, const QString& text);

    void undo() override;
    void redo() override;

private:
    std::function<void(double)> apply_;
    double before_, after_;
};

}  // namespace athlos::ui
