#pragma once
// Page 3 of the import wizard: every file is parsed in the background (a dry run) and every error
// is listed with file:line:column, as are names that exist already. Finish stays disabled until the
// list is empty; it then imports all files at once.
#include <QWizardPage>

class QCheckBox;
class QLabel;
class QListWidget;

namespace athlos::ui {

class ImportWizard;

class ImportWizardCheckPage : public QWizardPage {
    Q_OBJECT

public:
    explicit ImportWizardCheckPage(ImportWizard& wizard);
    void initializePage() override;
    bool isComplete() const override;

    // After Finish: the import's error, or empty.
    void showResult(const QString& error);
    QListWidget* problemList() const { return problems_; }
    QCheckBox* overwriteCheck() const { return overwrite_; }

private:
    void refresh();

    ImportWizard& wizard_;
    QLabel* summary_ = nullptr;
    QListWidget* problems_ = nullptr;
    QCheckBox* overwrite_ = nullptr;
    QLabel* result_ = nullptr;
};

}  // namespace athlos::ui
