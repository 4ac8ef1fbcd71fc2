#pragma once
// The action timeline of one recording (ActionTimeline) with a table of the classes (count,
// predicted, mean duration, mean confidence). Tool "View → Action timeline…" opens it in a dock
// that follows the window's time cursor; screenshot view `actions` shows a foot IMU's time series
// with its annotations and this timeline below it.
//
// Review: Previous/Next step through the predicted annotations in time order (cursor and visible
// range follow); Accept makes the current one a reviewed manual annotation, Reject deletes it —
// both through the window's AnnotationEditor, so they are undoable and journaled.
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <QWidget>
#include <vector>

class QComboBox;
class QLabel;
class QTableWidget;

namespace athlos {
class Project;
}

namespace athlos::ui {

class ActionTimeline;
class AnnotationEditor;
class TimeController;

class ActionsView : public QWidget {
    Q_OBJECT

public:
    ActionsView(const Project* project, TimeController* time, QWidget* parent = nullptr);

    // Recordings that have annotations, in name order.
    static QStringList annotatedRecordings(const Project& project);
    // The stream the predicted annotations of recording were computed from (provenance of the
    // first predicted output), else the recording's first stream; "rec/stream" or empty.
    static QString sourceStream(const Project& project, const QString& recording);

    Status setRecording(const QString& name);
    QString recording() const;
    // Re-reads the recording's annotations (after an edit or a processor run).
    void refresh();

    ActionTimeline* timeline() const { return timeline_; }
    QTableWidget* statsTable() const { return table_; }

    // Review of predicted annotations; without an editor Accept/Reject are disabled.
    void setEditor(AnnotationEditor* editor);
    int reviewIndex() const { return current_; }  // index in the recording's annotations, or -1
    bool reviewNext();
    bool reviewPrevious();
    Status acceptCurrent();
    Status rejectCurrent();

private:
    std::vector<int> predictedOrder() const;
    void goTo(int index);
    void advanceFrom(double t);
    void updateReview();

    const Project* project_;
    TimeController* time_ = nullptr;
    AnnotationEditor* editor_ = nullptr;
    int current_ = -1;
    QLabel* reviewLabel_ = nullptr;
    QWidget* acceptButton_ = nullptr;
    QWidget* rejectButton_ = nullptr;
    QComboBox* recordingCombo_ = nullptr;
    QLabel* summary_ = nullptr;
    ActionTimeline* timeline_ = nullptr;
    QTableWidget* table_ = nullptr;
};

}  // namespace athlos::ui
