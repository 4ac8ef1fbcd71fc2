#pragma once
// File ▸ Import Wizard…: pick files (or a folder with one file per athlete), check each file's
// preview and column mapping, see every error with file:line:column before anything is written,
// then import all files in the background, all-or-nothing (applyImport).
//
// Pages: ImportWizardFilesPage (files, recording and athlete names), ImportWizardMappingPage (per
// file: format, kind, preview, column → channel/unit mapping, names), ImportWizardCheckPage (dry
// run of every file, existing names, overwrite). Finish on the check page imports.
#include "core/io/ImportPreview.h"
#include "ui/BackgroundTask.h"

#include <QJsonObject>
#include <QWizard>
#include <functional>
#include <vector>

namespace athlos::ui {

class ImportWizardCheckPage;
class ImportWizardFilesPage;
class ImportWizardMappingPage;
class Workspace;

// Everything the wizard knows about one file.
struct ImportFileSettings {
    QString file;
    ImportOptions options;  // format, kind, columns, timeColumn, timeUnit (names and target: below)
    ImportPreview preview;  // for options.format / options.kind
    QString previewError;
    QString recording;
    QString stream;      // empty: the kind's default name
    QString athlete;     // stored in the recording's metadata
    QJsonObject roster;  // the file's roster row (number, team, position, mass_kg, ...), same place
};

class ImportWizard : public QWizard {
    Q_OBJECT

public:
    enum PageId { FilesPage, MappingPage, CheckPage };
    // Runs a job with progress and Cancel; BackgroundTask::run unless a test replaces it.
    using TaskRunner = std::function<BackgroundTask::Outcome(const QString& label, const BackgroundTask::Job& job)>;

    explicit ImportWizard(Workspace& workspace, QWidget* parent = nullptr);
    ~ImportWizard() override;

    // Files mode: recording named after each file, no athlete.
    void addFiles(const QStringList& files);
    // Folder mode: every importable file of dir, one per athlete (recording and athlete from the file name).
    int addFolder(const QString& dir);
    // Names the files' athletes from a roster CSV (file,athlete,number,team,position,mass_kg; the
    // CLI's --roster): rows match a file by name with or without its extension. Returns how many
    // files matched; warnings() lists files without a row and rows without a file.
    Expected<int> applyRoster(const QString& roster);
    void removeFile(int index);
    void clearFiles();

    std::vector<ImportFileSettings>& files() { return files_; }
    const std::vector<ImportFileSettings>& files() const { return files_; }
    // Re-reads the preview of file index with its format/kind; resetMapping: back to the suggestion.
    void refreshPreview(int index, bool resetMapping);
    // The options importFile() gets for file index (target, metadata, overwrite included).
    ImportOptions optionsFor(int index) const;

    bool overwrite() const { return overwrite_; }
    void setOverwrite(bool overwrite);
    // Dry run of all files in the background; problems() lists every error (file:line:column),
    // name clash and empty name. True if there are none.
    bool validateAll();
    bool validated() const { return validated_; }
    QStringList problems() const { return problems_; }
    // After validateAll(): the files' warnings and the roster's (applyRoster() sets those at once).
    QStringList warnings() const { return validated_ ? warnings_ : rosterWarnings_; }
    // Imports every file in the background and applies the result all-or-nothing. On failure or
    // Cancel the project is unchanged and lastError() says why.
    bool importAll();
    QString lastError() const { return error_; }
    QStringList importedPaths() const { return imported_; }

    void setTaskRunner(TaskRunner runner) { runner_ = std::move(runner); }
    // false: no progress dialog (tests); jobs still run off the GUI thread.
    void setShowProgress(bool show) { showProgress_ = show; }

    ImportWizardFilesPage* filesPage() const { return filesPage_; }
    ImportWizardMappingPage* mappingPage() const { return mappingPage_; }
    ImportWizardCheckPage* checkPage() const { return checkPage_; }

signals:
    void filesChanged();
    void validationChanged();

protected:
    bool validateCurrentPage() override;

private:
    void addFile(const QString& file, const QString& athlete);
    void updateProblems();
    BackgroundTask::Outcome runTask(const QString& label, const BackgroundTask::Job& job);

    Workspace& workspace_;
    std::vector<ImportFileSettings> files_;
    std::vector<ImportCheck> checks_;
    QStringList problems_;
    QStringList warnings_;
    QStringList rosterWarnings_;  // from the last applyRoster()
    QStringList imported_;
    QString error_;
    bool validated_ = false;
    bool overwrite_ = false;
    bool showProgress_ = true;
    TaskRunner runner_;
    ImportWizardFilesPage* filesPage_ = nullptr;
    ImportWizardMappingPage* mappingPage_ = nullptr;
    ImportWizardCheckPage* checkPage_ = nullptr;
};

}  // namespace athlos::ui
