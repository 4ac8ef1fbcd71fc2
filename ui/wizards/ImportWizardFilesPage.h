#pragma once
// Page 1 of the import wizard: the files, each with its recording and athlete name (editable).
// "Add Files…" takes many files (recording per file); "Add Folder…" takes every importable file of a
// folder as one athlete each (recording and athlete named after the file).
#include <QWizardPage>

class QTableWidget;
class QTableWidgetItem;

namespace athlos::ui {

class ImportWizard;

class ImportWizardFilesPage : public QWizardPage {
    Q_OBJECT

public:
    enum Column { FileColumn, RecordingColumn, AthleteColumn, FormatColumn };

    explicit ImportWizardFilesPage(ImportWizard& wizard);
    bool isComplete() const override;
    QTableWidget* table() const { return table_; }

private:
    void refresh();
    void onItemChanged(QTableWidgetItem* item);

    ImportWizard& wizard_;
    QTableWidget* table_ = nullptr;
    bool refreshing_ = false;
};

}  // namespace athlos::ui
