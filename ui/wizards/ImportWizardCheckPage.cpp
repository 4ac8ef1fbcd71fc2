#include "ui/wizards/ImportWizardCheckPage.h"

#include "ui/wizards/ImportWizard.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace athlos::ui {

ImportWizardCheckPage::ImportWizardCheckPage(ImportWizard& wizard) : wizard_(wizard) {
    setTitle(tr("Check"));
    setSubTitle(
        tr("Every file has been read without importing it. Fix the problems listed (go back to change "
           "the mapping or the names), then Finish imports all files at once."));
    setFinalPage(true);
    auto* layout = new QVBoxLayout(this);
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("checkSummary"));
    summary_->setWordWrap(true);
    layout->addWidget(summary_);
    problems_ = new QListWidget(this);
    problems_->setObjectName(QStringLiteral("problemList"));
    problems_->setWordWrap(true);
    layout->addWidget(problems_, 1);
    auto* row = new QHBoxLayout;
    overwrite_ = new QCheckBox(tr("Overwrite streams that exist in the project"), this);
    overwrite_->setObjectName(QStringLiteral("overwriteCheck"));
    auto* again = new QPushButton(tr("Check Again"), this);
    again->setObjectName(QStringLiteral("checkAgainButton"));
    row->addWidget(overwrite_);
    row->addStretch();
    row->addWidget(again);
    layout->addLayout(row);
    result_ = new QLabel(this);
    result_->setObjectName(QStringLiteral("importResultLabel"));
    result_->setWordWrap(true);
    result_->setStyleSheet(QStringLiteral("color: #b00020"));
    layout->addWidget(result_);

    connect(overwrite_, &QCheckBox::toggled, &wizard_, &ImportWizard::setOverwrite);
    connect(again, &QPushButton::clicked, &wizard_, &ImportWizard::validateAll);
    connect(&wizard_, &ImportWizard::validationChanged, this, &ImportWizardCheckPage::refresh);
}

void ImportWizardCheckPage::initializePage() {
    result_->clear();
    overwrite_->setChecked(wizard_.overwrite());
    wizard_.validateAll();
}

void ImportWizardCheckPage::refresh() {
    problems_->clear();
    const QStringList problems = wizard_.problems();
    for (const QString& problem : problems) {
        auto* item = new QListWidgetItem(problem, problems_);
        item->setForeground(QColor(0xb0, 0x00, 0x20));
    }
    for (const QString& warning : wizard_.warnings()) new QListWidgetItem(tr("Warning: %1").arg(warning), problems_);
    if (!wizard_.validated())
        summary_->setText(tr("Not checked yet."));
    else if (problems.isEmpty())
        summary_->setText(tr("All %1 file(s) can be imported.").arg(wizard_.files().size()));
    else
        summary_->setText(tr("%1 problem(s) must be fixed before importing.").arg(problems.size()));
    emit completeChanged();
}

bool ImportWizardCheckPage::isComplete() const {
    return wizard_.validated() && wizard_.problems().isEmpty() && !wizard_.files().empty();
}

void ImportWizardCheckPage::showResult(const QString& error) { result_->setText(error); }

}  // namespace athlos::ui
