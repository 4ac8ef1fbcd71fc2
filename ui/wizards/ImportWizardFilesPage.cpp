#include "ui/wizards/ImportWizardFilesPage.h"

#include "core/io/Importer.h"
#include "ui/wizards/ImportWizard.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace athlos::ui {

ImportWizardFilesPage::ImportWizardFilesPage(ImportWizard& wizard) : wizard_(wizard) {
    setTitle(tr("Files"));
    setSubTitle(
        tr("Choose the files to import: several at once, or a folder with one file per athlete. "
           "Recording and athlete names can be edited here or on the next page."));
    auto* layout = new QVBoxLayout(this);
    table_ = new QTableWidget(0, 4, this);
    table_->setObjectName(QStringLiteral("filesTable"));
    table_->setHorizontalHeaderLabels({tr("File"), tr("Recording"), tr("Athlete"), tr("Format")});
    table_->horizontalHeader()->setSectionResizeMode(FileColumn, QHeaderView::Stretch);
    table_->verticalHeader()->hide();
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    layout->addWidget(table_);

    auto* buttons = new QHBoxLayout;
    auto* addFiles = new QPushButton(tr("Add Files…"), this);
    addFiles->setObjectName(QStringLiteral("addFilesButton"));
    auto* addFolder = new QPushButton(tr("Add Folder (One File per Athlete)…"), this);
    addFolder->setObjectName(QStringLiteral("addFolderButton"));
    auto* roster = new QPushButton(tr("Apply Roster…"), this);
    roster->setObjectName(QStringLiteral("rosterButton"));
    roster->setToolTip(tr("A CSV file,athlete,number,team,position,mass_kg naming the athlete of each file"));
    auto* remove = new QPushButton(tr("Remove"), this);
    remove->setObjectName(QStringLiteral("removeButton"));
    buttons->addWidget(addFiles);
    buttons->addWidget(addFolder);
    buttons->addWidget(roster);
    buttons->addWidget(remove);
    buttons->addStretch();
    layout->addLayout(buttons);

    connect(addFiles, &QPushButton::clicked, this, [this] {
        QStringList filters;
        for (const auto& importer : importers()) {
            QStringList patterns;
            for (const QString& ext : importer->extensions()) patterns << QStringLiteral("*.") + ext;
            filters << QStringLiteral("%1 (%2)").arg(importer->description(), patterns.join(QLatin1Char(' ')));
        }
        filters.prepend(tr("All files (*)"));
        const QStringList files =
            QFileDialog::getOpenFileNames(this, tr("Import Files"), QString(), filters.join(QStringLiteral(";;")));
        if (!files.isEmpty()) wizard_.addFiles(files);
    });
    connect(addFolder, &QPushButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder with One File per Athlete"));
        if (!dir.isEmpty()) wizard_.addFolder(dir);
    });
    connect(roster, &QPushButton::clicked, this, [this] {
        const QString file =
            QFileDialog::getOpenFileName(this, tr("Roster"), QString(), tr("CSV files (*.csv);;All files (*)"));
        if (file.isEmpty()) return;
        const auto matched = wizard_.applyRoster(file);
        if (!matched)
            QMessageBox::warning(this, tr("Roster"), matched.message());
        else if (!wizard_.warnings().isEmpty())
            QMessageBox::information(this, tr("Roster"),
                                     tr("%n file(s) named from the roster.", nullptr, *matched) + QStringLiteral("\n") +
                                         wizard_.warnings().join(QLatin1Char('\n')));
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        QList<int> rows;
        for (const QModelIndex& index : table_->selectionModel()->selectedRows()) rows << index.row();
        std::sort(rows.begin(), rows.end(), std::greater<int>());
        for (int row : rows) wizard_.removeFile(row);
    });
    connect(table_, &QTableWidget::itemChanged, this, &ImportWizardFilesPage::onItemChanged);
    connect(&wizard_, &ImportWizard::filesChanged, this, &ImportWizardFilesPage::refresh);
}

void ImportWizardFilesPage::refresh() {
    const QSignalBlocker blocker(table_);
    const auto& files = wizard_.files();
    table_->setRowCount(int(files.size()));
    for (int r = 0; r < int(files.size()); ++r) {
        const ImportFileSettings& s = files[size_t(r)];
        auto* file = new QTableWidgetItem(QFileInfo(s.file).fileName());
        file->setToolTip(QDir::toNativeSeparators(s.file));
        file->setFlags(file->flags() & ~Qt::ItemIsEditable);
        table_->setItem(r, FileColumn, file);
        table_->setItem(r, RecordingColumn, new QTableWidgetItem(s.recording));
        table_->setItem(r, AthleteColumn, new QTableWidgetItem(s.athlete));
        auto* format = new QTableWidgetItem(s.previewError.isEmpty() ? s.preview.format : tr("unreadable"));
        format->setToolTip(s.previewError);
        format->setFlags(format->flags() & ~Qt::ItemIsEditable);
        table_->setItem(r, FormatColumn, format);
    }
    table_->resizeColumnToContents(RecordingColumn);
    table_->resizeColumnToContents(AthleteColumn);
    emit completeChanged();
}

void ImportWizardFilesPage::onItemChanged(QTableWidgetItem* item) {
    auto& files = wizard_.files();
    if (item->row() < 0 || item->row() >= int(files.size())) return;
    ImportFileSettings& s = files[size_t(item->row())];
    if (item->column() == RecordingColumn) s.recording = item->text().trimmed();
    if (item->column() == AthleteColumn) s.athlete = item->text().trimmed();
    emit completeChanged();
}

bool ImportWizardFilesPage::isComplete() const { return !wizard_.files().empty(); }

}  // namespace athlos::ui
