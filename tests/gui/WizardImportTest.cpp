// The import wizard, driven offscreen: files → mapping → check → Finish, against an in-memory
// project and a Workspace double. Values are checked in SI; failed, refused and cancelled imports
// must leave the project as it was.
#include "GuiTestSupport.h"
#include "WizardTestSupport.h"

#include "ui/MainWindow.h"
#include "ui/Workspace.h"
#include "ui/wizards/ImportWizard.h"
#include "ui/wizards/ImportWizardCheckPage.h"
#include "ui/wizards/ImportWizardFilesPage.h"
#include "ui/wizards/ImportWizardMappingPage.h"

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <numbers>

using namespace athlos;
using namespace athlos::ui;

namespace {

class RecordingWorkspace : public testing::WorkspaceDouble {
public:
    using WorkspaceDouble::WorkspaceDouble;
    Expected<RunOutcome> runProcessor(const RunRequest&) override { return makeError(QStringLiteral("not here")); }
};

// Every item of the project with its row count: equal snapshots mean an unchanged project.
QStringList snapshot(const Project& project) {
    QStringList items;
    for (const auto& [name, rec] : project.recordings()) {
        for (const auto& [item, stream] : rec.streams)
            items << name + '/' + item + ':' + QString::number(stream.info().rows);
        for (const auto& [item, table] : rec.tables) items << name + '/' + item;
        items << name + QStringLiteral(" metadata ") + QString::number(rec.metadata.size());
    }
    return items;
}

}  // namespace

class WizardImportTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { testing::isolateSettings(dir_.filePath(QStringLiteral("settings"))); }
    void init() { project_ = testing::makeProject(dir_.filePath(QStringLiteral("p.athlos"))); }

    void twoCsvsBecomeTwoRecordingsInSi() {
        const QString a = write(QStringLiteral("a/sprint1.csv"), exportText(1.0));
        const QString b = write(QStringLiteral("a/sprint2.csv"), exportText(2.0));
        RecordingWorkspace ws(project_.get());
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        wizard.addFiles({a, b});
        QCOMPARE(wizard.filesPage()->table()->rowCount(), 2);
        QCOMPARE(wizard.filesPage()->table()->item(1, ImportWizardFilesPage::RecordingColumn)->text(),
                 QStringLiteral("sprint2"));

        wizard.next();
        QCOMPARE(wizard.currentId(), int(ImportWizard::MappingPage));
        ImportWizardMappingPage* page = wizard.mappingPage();
        QCOMPARE(child<QComboBox>(&wizard, "formatCombo")->currentData().toString(), QStringLiteral("csv"));
        QCOMPARE(child<QComboBox>(&wizard, "kindCombo")->currentData().toString(), QStringLiteral("imu"));
        QCOMPARE(page->previewTable()->rowCount(), 3);
        QCOMPARE(page->previewTable()->item(0, 2)->text(), QStringLiteral("0.5"));
        QTableWidget* mapping = page->mappingTable();
        QCOMPARE(mapping->rowCount(), 5);
        QCOMPARE(mapping->item(1, ImportWizardMappingPage::ChannelColumn)->text(), QStringLiteral("t"));
        QCOMPARE(child<QComboBox>(&wizard, "timeColumnCombo")->currentText(), QStringLiteral("Time"));
        QCOMPARE(child<QComboBox>(&wizard, "timeUnitCombo")->currentText(), QStringLiteral("ms"));
        QCOMPARE(mapping->item(2, ImportWizardMappingPage::ChannelColumn)->text(), QStringLiteral("acc_x"));
        QCOMPARE(page->unitCombo(2)->currentText(), QStringLiteral("g"));
        QCOMPARE(mapping->item(3, ImportWizardMappingPage::ChannelColumn)->text(), QStringLiteral("gyr_z"));
        QCOMPARE(mapping->item(0, ImportWizardMappingPage::ImportColumn)->checkState(), Qt::Unchecked);  // Date: text
        QCOMPARE(mapping->item(2, ImportWizardMappingPage::StoredColumn)->text(), QStringLiteral("m/s^2"));
        QCOMPARE(mapping->item(3, ImportWizardMappingPage::StoredColumn)->text(), QStringLiteral("rad/s"));
        page->unitCombo(3)->setCurrentText(QStringLiteral("m"));  // a length is no angular rate
        QCOMPARE(mapping->item(3, ImportWizardMappingPage::StoredColumn)->text(), QStringLiteral("error"));
        QVERIFY(mapping->item(3, ImportWizardMappingPage::StoredColumn)
                    ->toolTip()
                    .contains(QStringLiteral("cannot be converted")));
        page->unitCombo(3)->setCurrentText(QStringLiteral("deg/s"));
        QCOMPARE(mapping->item(3, ImportWizardMappingPage::StoredColumn)->text(), QStringLiteral("rad/s"));
        grab(wizard, "import-wizard-mapping.png");
        // Edits: the "Load" column no kind knows is renamed; athlete and stream names.
        mapping->item(4, ImportWizardMappingPage::ChannelColumn)->setText(QStringLiteral("force"));
        child<QLineEdit>(&wizard, "athleteEdit")->setText(QStringLiteral("Anna"));
        child<QLineEdit>(&wizard, "streamEdit")->setText(QStringLiteral("wrist"));
        // Second file: skip the gyro.
        child<QComboBox>(&wizard, "fileCombo")->setCurrentIndex(1);
        QCOMPARE(child<QLineEdit>(&wizard, "athleteEdit")->text(), QString());
        mapping->item(3, ImportWizardMappingPage::ImportColumn)->setCheckState(Qt::Unchecked);

        wizard.next();
        QCOMPARE(wizard.currentId(), int(ImportWizard::CheckPage));
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        QVERIFY(wizard.button(QWizard::FinishButton)->isEnabled());
        wizard.button(QWizard::FinishButton)->click();
        QVERIFY2(wizard.lastError().isEmpty(), qPrintable(wizard.lastError()));
        QCOMPARE(wizard.result(), int(QDialog::Accepted));

        const Stream* s1 = project_->stream(QStringLiteral("sprint1/wrist"));
        const Stream* s2 = project_->stream(QStringLiteral("sprint2/imu"));
        QVERIFY(s1 && s2);
        QCOMPARE(s1->info().columnNames(), (QStringList{"acc_x", "gyr_z", "force"}));
        QCOMPARE(s2->info().columnNames(), (QStringList{"acc_x", "Load"}));
        QCOMPARE(s1->info().columns[0].unit, QStringLiteral("m/s^2"));
        QCOMPARE(s1->info().columns[1].unit, QStringLiteral("rad/s"));
        const StreamData& d1 = **s1->data();
        QCOMPARE(d1.rows(), std::size_t(3));
        QCOMPARE(d1.t[1], 0.01);
        QCOMPARE(d1.at(0, 0), 0.5 * 9.80665);
        QVERIFY(std::abs(d1.at(0, 1) - std::numbers::pi) < 1e-12);  // 180 deg/s
        const StreamData& d2 = **s2->data();
        QCOMPARE(d2.at(1, 0), 2.0 * 1.0 * 9.80665);
        QCOMPARE(project_->recording(QStringLiteral("sprint1"))->metadata.value("athlete").toString(),
                 QStringLiteral("Anna"));
        QCOMPARE(ws.modifications, 1);
        QCOMPARE(ws.shown, QStringLiteral("sprint1/wrist"));
        QVERIFY(project_->isModified());
    }

    void badCellIsListedWithLineAndNothingIsWritten() {
        const QString good = write(QStringLiteral("b/good.csv"), QByteArray("t,acc_x\n0,1\n0.01,2\n"));
        const QString bad =
            write(QStringLiteral("b/bad.csv"), QByteArray("t,acc_x,acc_y\n0,1,2\n0.01,1,2\n0.02,1,abc\n"));
        RecordingWorkspace ws(project_.get());
        const QStringList before = snapshot(*project_);
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        wizard.addFiles({good, bad});
        wizard.next();
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ImportWizard::CheckPage));
        QListWidget* list = wizard.checkPage()->problemList();
        QVERIFY(list->count() >= 1);
        QVERIFY2(list->item(0)->text().contains(QStringLiteral("bad.csv:4:3 (column 'acc_y'): 'abc' is not a number")),
                 qPrintable(list->item(0)->text()));
        QVERIFY(!wizard.button(QWizard::FinishButton)->isEnabled());
        QVERIFY(!wizard.checkPage()->isComplete());
        grab(wizard, "import-wizard-check.png");
        wizard.accept();  // refused while problems exist
        QVERIFY(wizard.isVisible());
        QCOMPARE(snapshot(*project_), before);
        QCOMPARE(ws.modifications, 0);

        // Going back and skipping the bad column fixes it.
        wizard.back();
        child<QComboBox>(&wizard, "fileCombo")->setCurrentIndex(1);
        wizard.mappingPage()
            ->mappingTable()
            ->item(2, ImportWizardMappingPage::ImportColumn)
            ->setCheckState(Qt::Unchecked);
        wizard.next();
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        QVERIFY(wizard.button(QWizard::FinishButton)->isEnabled());
    }

    void folderIsOneFilePerAthlete() {
        write(QStringLiteral("team/anna.csv"), QByteArray("t,acc_x\n0,1\n0.01,2\n"));
        write(QStringLiteral("team/ben.csv"), QByteArray("t,acc_x\n0,3\n0.01,4\n"));
        write(QStringLiteral("team/notes.md"), QByteArray("not data\n"));
        RecordingWorkspace ws(project_.get());
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        QCOMPARE(wizard.addFolder(dir_.filePath(QStringLiteral("team"))), 2);
        QTableWidget* table = wizard.filesPage()->table();
        QCOMPARE(table->item(0, ImportWizardFilesPage::AthleteColumn)->text(), QStringLiteral("anna"));
        QCOMPARE(table->item(1, ImportWizardFilesPage::RecordingColumn)->text(), QStringLiteral("ben"));
        table->item(0, ImportWizardFilesPage::AthleteColumn)->setText(QStringLiteral("Anna Berg"));
        table->item(1, ImportWizardFilesPage::RecordingColumn)->setText(QStringLiteral("ben-run"));
        wizard.next();
        QCOMPARE(child<QLineEdit>(&wizard, "athleteEdit")->text(), QStringLiteral("Anna Berg"));
        wizard.next();
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        QVERIFY(wizard.importAll());
        QCOMPARE(project_->recording(QStringLiteral("anna"))->metadata.value("athlete").toString(),
                 QStringLiteral("Anna Berg"));
        QCOMPARE(project_->recording(QStringLiteral("ben-run"))->metadata.value("athlete").toString(),
                 QStringLiteral("ben"));
        QCOMPARE((**project_->stream(QStringLiteral("ben-run/imu"))->data()).at(1, 0), 4.0);
    }

    // Clock times with the date given, a text label column into annotations, a roster naming the
    // athlete: the wizard offers what `athlos import` does (--time-column, --date, --labels,
    // --label-names, --roster).
    void clockTimesLabelsAndRoster() {
        QByteArray text = "Time,acc_x,acc_y,acc_z,label\n";
        for (int i = 0; i < 6; ++i)
            text += "10:00:00." + QByteArray::number(10 * i).rightJustified(3, '0') + ",0,0,9.81," +
                    (i < 4 ? "0" : "1") + "\n";
        const QString file = write(QStringLiteral("g/walk.csv"), text);
        const QString roster =
            write(QStringLiteral("g/roster.csv"), QByteArray("file,athlete,number\nwalk,Anna Berg,7\nghost.csv,X,1\n"));
        RecordingWorkspace ws(project_.get());
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        QCOMPARE(wizard.addFolder(QFileInfo(file).absolutePath()), 2);  // the roster too, at first
        const auto matched = wizard.applyRoster(roster);
        QVERIFY(matched);
        QCOMPARE(*matched, 1);
        QCOMPARE(int(wizard.files().size()), 1);  // the roster is not a recording
        QCOMPARE(wizard.files()[0].athlete, QStringLiteral("Anna Berg"));
        QVERIFY(wizard.warnings().join('\n').contains(QStringLiteral("'ghost.csv' is in the roster")));
        QVERIFY(!wizard.applyRoster(file));  // no 'file' column: refused, naming it

        wizard.next();
        child<QComboBox>(&wizard, "kindCombo")
            ->setCurrentIndex(child<QComboBox>(&wizard, "kindCombo")->findData("imu"));
        auto* timeColumn = child<QComboBox>(&wizard, "timeColumnCombo");
        timeColumn->setCurrentIndex(timeColumn->findText(QStringLiteral("Time")));
        child<QComboBox>(&wizard, "timeUnitCombo")->setCurrentText(QStringLiteral("hh:mm:ss.fff"));
        child<QLineEdit>(&wizard, "dateEdit")->setText(QStringLiteral("2024-05-01"));
        auto* labels = child<QComboBox>(&wizard, "labelCombo");
        labels->setCurrentIndex(labels->findText(QStringLiteral("label")));
        child<QLineEdit>(&wizard, "labelNamesEdit")->setText(QStringLiteral("stand,walk"));
        QVERIFY(!wizard.mappingPage()->validatePage());  // not VALUE=NAME pairs
        QVERIFY(child<QLabel>(&wizard, "previewErrorLabel")->text().contains(QStringLiteral("walk.csv: label names")));
        child<QLineEdit>(&wizard, "labelNamesEdit")->setText(QStringLiteral("0=stand,1=walk"));
        QVERIFY(wizard.mappingPage()->validatePage());
        const ImportOptions options = wizard.optionsFor(0);
        QCOMPARE(options.timeColumn, QStringLiteral("Time"));
        QCOMPARE(options.date, QStringLiteral("2024-05-01"));
        QCOMPARE(options.labelColumn, QStringLiteral("label"));
        QCOMPARE(options.labelNames.at(QStringLiteral("1")), QStringLiteral("walk"));
        QCOMPARE(options.metadata.value(QStringLiteral("number")).toInt(), 7);

        wizard.next();
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        QVERIFY2(wizard.importAll(), qPrintable(wizard.lastError()));
        const Stream* stream = project_->stream(QStringLiteral("walk/imu"));
        QVERIFY(stream);
        QCOMPARE(stream->info().columnNames(), (QStringList{"acc_x", "acc_y", "acc_z"}));
        QCOMPARE(stream->info().attributes.value(QStringLiteral("t0_utc")).toString(),
                 QStringLiteral("2024-05-01T10:00:00Z"));
        QCOMPARE((**stream->data()).t[5], 0.05);
        const Recording* recording = project_->recording(QStringLiteral("walk"));
        QCOMPARE(recording->metadata.value(QStringLiteral("athlete")).toString(), QStringLiteral("Anna Berg"));
        QCOMPARE(int(recording->annotations.size()), 2);
        QCOMPARE(recording->annotations[0].label, QStringLiteral("stand"));
        QCOMPARE(recording->annotations[1].label, QStringLiteral("walk"));
        QCOMPARE(recording->annotations[1].tStart, 0.04);
    }

    // A gaitmap file whose first column is a sample index: the rate typed in the wizard is used
    // (athlos import --rate), and the field is off for formats that have a time column.
    void gaitmapSampleIndexRate() {
        QByteArray text =
            ",left_sensor,left_sensor,left_sensor,left_sensor,left_sensor,left_sensor\n"
            ",acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
        for (int i = 0; i < 50; ++i) text += QByteArray::number(i) + ",0,0,9.81,0,0,0\n";
        const QString file = write(QStringLiteral("gm/walk.csv"), text);
        RecordingWorkspace ws(project_.get());
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        wizard.addFiles({file});
        wizard.next();
        auto* format = child<QComboBox>(&wizard, "formatCombo");
        auto* rate = child<QDoubleSpinBox>(&wizard, "rateSpin");
        format->setCurrentIndex(format->findData(QStringLiteral("csv")));
        QVERIFY(!rate->isEnabled());
        format->setCurrentIndex(format->findData(QStringLiteral("gaitmap")));
        QVERIFY(rate->isEnabled());
        QCOMPARE(rate->value(), 0.0);  // "from the motion"
        rate->setValue(204.8);
        QVERIFY(wizard.mappingPage()->validatePage());
        QCOMPARE(wizard.optionsFor(0).rate, 204.8);
        wizard.next();
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        QVERIFY2(wizard.importAll(), qPrintable(wizard.lastError()));
        const Stream* stream = project_->stream(QStringLiteral("walk/left-foot"));
        QVERIFY(stream);
        QCOMPARE(stream->info().attributes.value(QStringLiteral("sampling_rate_source")).toString(),
                 QStringLiteral("given"));
        QVERIFY(std::abs((**stream->data()).t[10] - 10.0 / 204.8) < 1e-12);
    }

    void existingNamesAreFlaggedUntilOverwrite() {
        const QString file = write(QStringLiteral("c/run1.csv"), QByteArray("t,acc_x\n0,1\n0.01,2\n"));
        RecordingWorkspace ws(project_.get());
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        wizard.addFiles({file});
        wizard.next();
        wizard.next();
        QCOMPARE(wizard.problems().size(), 1);
        QVERIFY(wizard.problems().front().contains(QStringLiteral("'run1/imu' already exists")));
        QVERIFY(!wizard.button(QWizard::FinishButton)->isEnabled());
        wizard.checkPage()->overwriteCheck()->setChecked(true);
        QVERIFY(wizard.problems().isEmpty());
        QVERIFY(wizard.button(QWizard::FinishButton)->isEnabled());
        wizard.accept();
        QVERIFY2(wizard.lastError().isEmpty(), qPrintable(wizard.lastError()));
        QCOMPARE(project_->stream(QStringLiteral("run1/imu"))->info().rows, 2);
    }

    void beaconTableHasNoTimeColumn() {
        const QString file = write(QStringLiteral("e/anchors.csv"), QByteArray("id,x,y,z\nB1,0,0,2\nB2,10,0,2\n"));
        RecordingWorkspace ws(project_.get());
        ImportWizard wizard(ws);
        wizard.setShowProgress(false);
        wizard.show();
        wizard.addFiles({file});
        wizard.next();
        QCOMPARE(child<QComboBox>(&wizard, "kindCombo")->currentData().toString(), QStringLiteral("beacons"));
        QCOMPARE(child<QComboBox>(&wizard, "timeColumnCombo")->currentIndex(), 0);
        wizard.next();
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        QVERIFY(wizard.importAll());
        const Table* table = project_->table(QStringLiteral("anchors/beacons"));
        QVERIFY(table);
        QCOMPARE(table->rows(), 2);
        QCOMPARE(ws.shown, QString());  // no stream to show
    }

    void cancelLeavesProjectUnchanged() {
        const QString a = write(QStringLiteral("d/x1.csv"), exportText(1.0));
        const QString b = write(QStringLiteral("d/x2.csv"), exportText(2.0));
        RecordingWorkspace ws(project_.get());
        const QStringList before = snapshot(*project_);
        ImportWizard wizard(ws);
        bool cancelImport = false;
        int jobs = 0;
        // Runs the job as BackgroundTask would, pressing Cancel once the first file is done.
        wizard.setTaskRunner([&](const QString&, const BackgroundTask::Job& job) {
            ++jobs;
            CancelToken token;
            Progress progress(
                [&](double fraction, const QString&) {
                    if (cancelImport && fraction >= 0.5) token.cancel();
                },
                token);
            BackgroundTask::Outcome outcome;
            outcome.status = job(progress);
            outcome.cancelled = token.isCancelled();
            return outcome;
        });
        wizard.show();
        wizard.addFiles({a, b});
        wizard.next();
        wizard.next();
        QVERIFY2(wizard.problems().isEmpty(), qPrintable(wizard.problems().join('\n')));
        cancelImport = true;
        wizard.accept();
        QCOMPARE(jobs, 2);  // the check, then the import
        QVERIFY(wizard.isVisible());
        QVERIFY(wizard.lastError().contains(QStringLiteral("cancelled")));
        QCOMPARE(snapshot(*project_), before);
        QCOMPARE(ws.modifications, 0);
        QVERIFY(!project_->stream(QStringLiteral("x1/imu")));
    }

    void launchesFromFileMenu() {
        MainWindow window;
        window.setInteractive(false);
        window.setProject(std::shared_ptr<Project>(testing::makeProject(dir_.filePath(QStringLiteral("m.athlos")))));
        auto* action = window.findChild<QAction*>(QStringLiteral("import-wizard"));
        QVERIFY(action);
        action->trigger();
        auto* wizard = window.findChild<ImportWizard*>();
        QVERIFY(wizard);
        QCOMPARE(wizard->currentId(), int(ImportWizard::FilesPage));
        wizard->reject();
    }

private:
    template <class T>
    static T* child(QObject* parent, const char* name) {
        T* w = parent->findChild<T*>(QString::fromLatin1(name));
        if (!w) qFatal("no child %s", name);
        return w;
    }

    // ATHLOS_GRAB_DIR=<dir>: saves the page as a PNG there, to look at.
    static void grab(QWidget& widget, const char* name) {
        const QString dir = qEnvironmentVariable("ATHLOS_GRAB_DIR");
        if (!dir.isEmpty()) widget.grab().save(QDir(dir).filePath(QString::fromLatin1(name)));
    }

    // A sports-watch export: a text date, time in ms, acc in g, gyro in deg/s, and a column no kind knows.
    static QByteArray exportText(double scale) {
        QByteArray text = "Date;Time [ms];AccX [g];GyroZ [deg/s];Load\n";
        for (int i = 0; i < 3; ++i)
            text += "2024-05-01;" + QByteArray::number(10 * i) + ';' + QByteArray::number(scale * (0.5 + 0.5 * i)) +
                    ';' + QByteArray::number(180 - 90 * i) + ';' + QByteArray::number(i) + '\n';
        return text;
    }

    QString write(const QString& name, const QByteArray& content) {
        const QString path = dir_.filePath(name);
        QDir().mkpath(QFileInfo(path).absolutePath());
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
        f.write(content);
        return path;
    }

    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
};

QTEST_MAIN(WizardImportTest)
#include "WizardImportTest.moc"
