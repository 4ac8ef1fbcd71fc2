#pragma once
// The annotation dock: the project's classes (with their colours and number keys; the current
// one is used for new intervals), the annotations of the shown recording, and review of
// processor-made annotations (next, accept, reject — both undoable).
#include <QString>
#include <QWidget>

class QLabel;
class QListWidget;
class QTableWidget;

namespace athlos::ui {

class AnnotationEditor;
class AnnotationLayer;

class AnnotationPanel : public QWidget {
    Q_OBJECT

public:
    AnnotationPanel(AnnotationEditor* editor, AnnotationLayer* layer, QWidget* parent = nullptr);

    QListWidget* classList() const { return classes_; }
    QTableWidget* annotationTable() const { return table_; }

public slots:
    void refresh();
    // Selects the next annotation (after the selected one) whose source is a processor.
    bool reviewNext();
    void acceptSelected();
    void rejectSelected();
    void addClassDialog();

private:
    int selectedRow() const;

    AnnotationEditor* editor_ = nullptr;
    AnnotationLayer* layer_ = nullptr;
    QListWidget* classes_ = nullptr;
    QTableWidget* table_ = nullptr;
    QLabel* status_ = nullptr;
    bool refreshing_ = false;
};

}  // namespace athlos::ui
