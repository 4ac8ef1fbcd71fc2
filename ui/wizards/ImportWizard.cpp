#include "ui/wizards/ImportWizard.h"

#include "core/io/Importer.h"
#include "core/io/MultiImport.h"
#include "core/model/Project.h"
#include "core/model/StreamKinds.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/wizards/ImportWizardCheckPage.h"
#include "ui/wizards/ImportWizardFilesPage.h"
#include "ui/wizards/ImportWizardMappingPage.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QSet>
#include <memory>

namespace athlos::ui {

ImportWizard::ImportWizard(Workspace& workspace, QWidget* parent) : QWizard(parent), workspace_(workspace) {
    setObjectName(QStringLiteral("importWizard"));
    setWindowTitle(tr("Import Wizard"));
    setOption(QWizard::NoBackButtonOnStartPage);
    filesPage_ = new ImportWizardFilesPage(*this);
    mappingPage_ = new ImportWizardMappingPage(*this);
    checkPage_ = new ImportWizardCheckPage(*this);
    setPage(FilesPage, filesPage_);
    setPage(MappingPage, mappingPage_);
    setPage(CheckPage, checkPage_);
    resize(900, 640);
}

ImportWizard::~ImportWizard() = default;

void ImportWizard::addFile(const QString& file, const QString& athlete) {
    const QString path = QFileInfo(file).absoluteFilePath();
    for (const ImportFileSettings& existing : files_)
        if (existing.file == path) return;
    ImportFileSettings settings;
    settings.file = path;
    settings.recording = QFileInfo(file).completeBaseName();
    settings.athlete = athlete;
    settings.options.format = QStringLiteral("auto");
    files_.push_back(settings);
    refreshPreview(int(files_.size()) - 1, true);
}

void ImportWizard::addFiles(const QStringList& files) {
    for (const QString& file : files) addFile(file, {});
    validated_ = false;
    emit filesChanged();
}

int ImportWizard::addFolder(const QString& dir) {
    QSet<QString> extensions;
    for (const auto& importer : importers())
        for (const QString& ext : importer->extensions()) extensions.insert(ext);
    int added = 0;
    const QFileInfoList entries = QDir(dir).entryInfoList(QDir::Files | QDir::Readable, QDir::Name);
    for (const QFileInfo& entry : entries) {
        if (!extensions.contains(entry.suffix().toLower())) continue;
        addFile(entry.absoluteFilePath(), entry.completeBaseName());
        ++added;
    }
    validated_ = false;
    emit filesChanged();
    return added;
}

Expected<int> ImportWizard::applyRoster(const QString& roster) {
    auto entries = readRoster(roster);
    if (!entries) return entries.error();
    std::vector<bool> used(entries->size(), false);
    int matched = 0;
    rosterWarnings_.clear();
    // A roster kept in the folder of the recordings is not a recording.
    const QString rosterPath = QFileInfo(roster).absoluteFilePath();
    std::erase_if(files_, [&](const ImportFileSettings& s) { return s.file == rosterPath; });
    const QString rosterName = QFileInfo(roster).fileName();
    for (ImportFileSettings& s : files_) {
        const QFileInfo f(s.file);
        const auto entry = std::find_if(entries->begin(), entries->end(), [&](const RosterEntry& e) {
            return e.file == f.fileName() || e.file == f.completeBaseName();
        });
        if (entry == entries->end()) {
            rosterWarnings_ << tr("%1: not in the roster %2").arg(f.fileName(), rosterName);
            continue;
        }
        used[std::size_t(entry - entries->begin())] = true;
        s.roster = entry->attributes;
        if (const QString athlete = entry->attributes.value(QStringLiteral("athlete")).toString(); !athlete.isEmpty())
            s.athlete = athlete;
        ++matched;
    }
    for (std::size_t i = 0; i < entries->size(); ++i)
        if (!used[i])
            rosterWarnings_
                << tr("%1: '%2' is in the roster but not among the files").arg(rosterName, (*entries)[i].file);
    validated_ = false;
    emit filesChanged();
    return matched;
}

void ImportWizard::removeFile(int index) {
    if (index < 0 || index >= int(files_.size())) return;
    files_.erase(files_.begin() + index);
    validated_ = false;
    emit filesChanged();
}

void ImportWizard::clearFiles() {
    files_.clear();
    validated_ = false;
    emit filesChanged();
}

void ImportWizard::refreshPreview(int index, bool resetMapping) {
    ImportFileSettings& s = files_[size_t(index)];
    auto preview = previewFile(s.file, s.options.format, 20, s.options.kind);
    if (!preview) {
        s.preview = {};
        s.previewError = preview.message();
        return;
    }
    s.previewError.clear();
    s.preview = *preview;
    if (s.options.format.isEmpty() || s.options.format == QLatin1String("auto"))
        s.options.format = s.preview.format;  // show (and keep) what was detected
    if (resetMapping) {
        const ImportOptions suggested = suggestedOptions(s.preview);
        s.options.columns = suggested.columns;
        s.options.timeColumn = suggested.timeColumn;
        s.options.timeUnit = suggested.timeUnit;
        if (s.options.kind.isEmpty() && s.options.format == QLatin1String("csv")) s.options.kind = suggested.kind;
    }
    validated_ = false;
}

ImportOptions ImportWizard::optionsFor(int index) const {
    const ImportFileSettings& s = files_[size_t(index)];
    ImportOptions options = s.options;
    options.target = s.stream.trimmed().isEmpty() ? s.recording.trimmed()
                                                  : s.recording.trimmed() + QLatin1Char('/') + s.stream.trimmed();
    options.overwrite = overwrite_;
    for (auto it = s.roster.begin(); it != s.roster.end(); ++it) options.metadata.insert(it.key(), it.value());
    if (!s.athlete.trimmed().isEmpty()) options.metadata.insert(QStringLiteral("athlete"), s.athlete.trimmed());
    return options;
}

void ImportWizard::setOverwrite(bool overwrite) {
    overwrite_ = overwrite;
    if (validated_) updateProblems();
}

BackgroundTask::Outcome ImportWizard::runTask(const QString& label, const BackgroundTask::Job& job) {
    if (runner_) return runner_(label, job);
    return BackgroundTask::run(this, label, job, showProgress_);
}

bool ImportWizard::validateAll() {
    checks_.clear();
    validated_ = false;
    std::vector<std::pair<QString, ImportOptions>> jobs;
    for (int i = 0; i < int(files_.size()); ++i) jobs.emplace_back(files_[size_t(i)].file, optionsFor(i));
    auto checks = std::make_shared<std::vector<ImportCheck>>();
    const BackgroundTask::Outcome outcome =
        runTask(tr("Checking %1 file(s)…").arg(jobs.size()), [jobs, checks](const Progress& progress) -> Status {
            const double n = double(jobs.size());
            for (size_t i = 0; i < jobs.size(); ++i) {
                if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
                checks->push_back(
                    checkImport(jobs[i].first, jobs[i].second, progress.sub(double(i) / n, double(i + 1) / n)));
            }
            return {};
        });
    if (outcome.cancelled || !outcome.status) {
        problems_ = {outcome.cancelled ? tr("The check was cancelled; check again before importing.")
                                       : outcome.status.message()};
        warnings_.clear();
        emit validationChanged();
        return false;
    }
    checks_ = std::move(*checks);
    validated_ = true;
    updateProblems();
    return problems_.isEmpty();
}

void ImportWizard::updateProblems() {
    problems_.clear();
    warnings_ = rosterWarnings_;
    const Project* project = workspace_.project();
    QSet<QString> seen;
    for (size_t i = 0; i < files_.size() && i < checks_.size(); ++i) {
        const ImportFileSettings& s = files_[i];
        const QString name = QFileInfo(s.file).fileName();
        if (s.recording.trimmed().isEmpty()) problems_ << tr("%1: the recording name is empty").arg(name);
        problems_ << checks_[i].errors;
        warnings_ << checks_[i].warnings;
        for (const QString& path : checks_[i].items) {
            if (seen.contains(path))
                problems_ << tr("%1: '%2' is imported from another file as well; give it another name").arg(name, path);
            seen.insert(path);
            if (!overwrite_ && project && (project->stream(path) || project->table(path)))
                problems_
                    << tr("%1: '%2' already exists in the project (tick overwrite to replace it)").arg(name, path);
        }
    }
    emit validationChanged();
}

bool ImportWizard::importAll() {
    error_.clear();
    imported_.clear();
    Project* project = workspace_.project();
    if (!project) {
        error_ = tr("Create or open a project first, then import recordings into it.");
        return false;
    }
    std::vector<std::pair<QString, ImportOptions>> jobs;
    for (int i = 0; i < int(files_.size()); ++i) jobs.emplace_back(files_[size_t(i)].file, optionsFor(i));
    auto merged = std::make_shared<ImportResult>();
    const BackgroundTask::Outcome outcome =
        runTask(tr("Importing %1 file(s)…").arg(jobs.size()), [jobs, merged](const Progress& progress) -> Status {
            const double n = double(jobs.size());
            for (size_t i = 0; i < jobs.size(); ++i) {
                auto result = importFile(jobs[i].first, jobs[i].second, progress.sub(double(i) / n, double(i + 1) / n));
                if (!result) return result.error();
                if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
                for (ImportedItem& item : result->items) merged->items.push_back(std::move(item));
                merged->warnings << result->warnings;
                for (auto& [recording, metadata] : result->recordingMetadata)
                    for (auto it = metadata.begin(); it != metadata.end(); ++it)
                        merged->recordingMetadata[recording].insert(it.key(), it.value());
                // Label columns become annotations; the first GNSS file may set the project's origin.
                for (auto& [recording, annotations] : result->annotations) {
                    auto& list = merged->annotations[recording];
                    list.insert(list.end(), annotations.begin(), annotations.end());
                }
                if (!merged->origin) merged->origin = result->origin;
                progress.report(double(i + 1) / n);
            }
            return {};
        });
    if (outcome.cancelled) {
        error_ = tr("Import cancelled; the project is unchanged.");
        return false;
    }
    if (!outcome.status) {
        error_ = tr("Nothing was imported.\n\n%1").arg(outcome.status.message());
        return false;
    }
    QStringList paths;
    for (const ImportedItem& item : merged->items) paths << item.path;
    if (Status applied = applyImport(*project, std::move(*merged), overwrite_); !applied) {
        error_ = tr("Nothing was imported.\n\n%1").arg(applied.message());
        return false;
    }
    project->setModified(true);
    imported_ = paths;
    workspace_.projectModified();
    for (const QString& path : paths)
        if (project->stream(path)) {
            workspace_.showItem(path);
            break;
        }
    return true;
}

bool ImportWizard::validateCurrentPage() {
    if (currentId() == CheckPage) {
        if (!validated_ || !problems_.isEmpty()) return false;
        const bool ok = importAll();
        checkPage_->showResult(ok ? QString() : error_);
        return ok;
    }
    return QWizard::validateCurrentPage();
}

namespace {

void launchImportWizard(Workspace& workspace) {
    if (!workspace.project()) {
        QMessageBox::information(workspace.window(), ImportWizard::tr("Import Wizard"),
                                 ImportWizard::tr("Create or open a project first, then import recordings into it."));
        return;
    }
    auto* wizard = new ImportWizard(workspace, workspace.window());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->open();
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("import-wizard"), QT_TRANSLATE_NOOP("Tools", "Import Wizard…"),
                      QT_TRANSLATE_NOOP("Tools", "File"), launchImportWizard});

}  // namespace athlos::ui
