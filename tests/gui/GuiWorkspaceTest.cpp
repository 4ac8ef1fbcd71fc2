// The main window as a Workspace: registered tools appear in their menus and receive the
// workspace; the generic processor dialog builds its form from a schema and runs a real
// processor (resample from the signal plugin) into the tree with provenance; re-run pre-fills
// the dialog from that provenance.
#include "GuiTestSupport.h"
#include "core/processing/ProcessorRegistry.h"
#include "ui/MainWindow.h"
#include "ui/ParameterForm.h"
#include "ui/ProcessorDialog.h"
#include "ui/ProjectTreeModel.h"
#include "ui/ToolRegistry.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QMenuBar>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

using namespace athlos;
using namespace athlos::ui;

namespace {

int launchedCount = 0;
Workspace* launchedWith = nullptr;

// Registered like a wizard would be, at static initialisation of this executable.
ATHLOS_REGISTER_TOOL({QStringLiteral("test-tool"), QT_TRANSLATE_NOOP("Tools", "Test Tool…"),
                      QT_TRANSLATE_NOOP("Tools", "Testing"), [](Workspace& workspace) {
                          ++launchedCount;
                          launchedWith = &workspace;
                      }});

// A processor with every parameter type, to check the generated form without a plugin.
class SchemaProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("test-schema"); }
    QString name() const override { return QStringLiteral("Schema"); }
    QString description() const override { return QStringLiteral("all parameter types"); }
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override {
        ParameterSpec optional = ParameterSpec::number(QStringLiteral("rate"), std::nan(""), 0.5, 100.0,
                                                       QStringLiteral("Hz"), QStringLiteral("output rate"));
        optional.optional = true;
        return {ParameterSpec::number(QStringLiteral("cutoff"), 5.0, 0.1, 50.0, QStringLiteral("Hz"),
                                      QStringLiteral("cut-off frequency")),
                ParameterSpec::integer(QStringLiteral("order"), 4, 1, 8, QStringLiteral("filter order")),
                ParameterSpec::boolean(QStringLiteral("zero_phase"), true, QStringLiteral("forward-backward")),
                ParameterSpec::choice(QStringLiteral("type"), {QStringLiteral("low"), QStringLiteral("high")},
                                      QStringLiteral("high"), QStringLiteral("filter type")),
                ParameterSpec::text(QStringLiteral("columns"), QStringLiteral("acc_*"), QStringLiteral("columns")),
                optional};
    }
    QList<InputSpec> inputs() const override {
        return {InputSpec{QStringLiteral("signal"), {QStringLiteral("lps-position")}, false, false, {}}};
    }
    QList<OutputSpec> outputs() const override { return {OutputSpec{}}; }
    Expected<std::vector<ProcessorOutput>> run(const RunContext&) const override {
        return makeError(QStringLiteral("not meant to run"));
    }
};

}  // namespace

class GuiWorkspaceTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void registeredToolsAppearInTheirMenu();
    void formFollowsTheSchema();
    void dialogRunsResampleIntoTheTree();
    void rerunPrefillsFromProvenance();
    void invalidParametersStayInTheDialog();

private:
    QTemporaryDir dir_;
};

void GuiWorkspaceTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
    ProcessorRegistry::instance().add(std::make_shared<SchemaProcessor>());
    QVERIFY2(ProcessorRegistry::instance().find(QStringLiteral("resample")),
             qPrintable(ProcessorRegistry::instance().loadErrors().join(QLatin1Char('\n'))));
}

void GuiWorkspaceTest::registeredToolsAppearInTheirMenu() {
    MainWindow window;
    window.setInteractive(false);
    QAction* action = window.toolAction(QStringLiteral("test-tool"));
    QVERIFY(action);
    QCOMPARE(action->text(), QStringLiteral("Test Tool…"));
    bool inTestingMenu = false;
    for (QAction* menuAction : window.menuBar()->actions())
        if (menuAction->menu() && menuAction->text() == QStringLiteral("Testing"))
            inTestingMenu = menuAction->menu()->actions().contains(action);
    QVERIFY(inTestingMenu);
    QVERIFY(!action->isEnabled());  // no project yet

    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("tools.athlos"))));
    QVERIFY(action->isEnabled());
    action->trigger();
    QCOMPARE(launchedCount, 1);
    QCOMPARE(launchedWith, static_cast<Workspace*>(&window));
    QCOMPARE(static_cast<Workspace&>(window).window(), static_cast<QWidget*>(&window));
}

void GuiWorkspaceTest::formFollowsTheSchema() {
    MainWindow window;
    window.setInteractive(false);
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("schema.athlos"))));
    ProcessorDialog dialog(window);
    QVERIFY(dialog.selectProcessor(QStringLiteral("test-schema")));

    ParameterForm* form = dialog.parameterForm();
    auto* cutoff = qobject_cast<QDoubleSpinBox*>(form->editor(QStringLiteral("cutoff")));
    QVERIFY(cutoff);
    QCOMPARE(cutoff->minimum(), 0.1);
    QCOMPARE(cutoff->maximum(), 50.0);
    QCOMPARE(cutoff->value(), 5.0);
    QCOMPARE(cutoff->suffix(), QStringLiteral(" Hz"));
    QCOMPARE(cutoff->toolTip(), QStringLiteral("cut-off frequency"));
    auto* order = qobject_cast<QSpinBox*>(form->editor(QStringLiteral("order")));
    QVERIFY(order);
    QCOMPARE(order->maximum(), 8);
    QVERIFY(qobject_cast<QCheckBox*>(form->editor(QStringLiteral("zero_phase"))));
    auto* type = qobject_cast<QComboBox*>(form->editor(QStringLiteral("type")));
    QVERIFY(type);
    QCOMPARE(type->count(), 2);
    QCOMPARE(type->currentText(), QStringLiteral("high"));
    QVERIFY(qobject_cast<QLineEdit*>(form->editor(QStringLiteral("columns"))));

    // Optional: absent until enabled.
    QVERIFY(form->enableBox(QStringLiteral("rate")));
    QVERIFY(!form->enableBox(QStringLiteral("cutoff")));
    QVERIFY(!form->values().contains(QStringLiteral("rate")));
    QVERIFY(!form->editor(QStringLiteral("rate"))->isEnabled());
    form->enableBox(QStringLiteral("rate"))->setChecked(true);
    QVERIFY(form->editor(QStringLiteral("rate"))->isEnabled());
    QVERIFY(form->values().contains(QStringLiteral("rate")));

    // Inputs are filtered by kind: only the position stream qualifies.
    QComboBox* input = dialog.inputBox(0);
    QVERIFY(input);
    QCOMPARE(input->count(), 1);
    QCOMPARE(input->itemData(0).toString(), QStringLiteral("run1/lps"));
    QCOMPARE(dialog.outputEdit()->text(), QStringLiteral("run1/lps-test-schema"));
    QVERIFY(dialog.validate());
}

void GuiWorkspaceTest::dialogRunsResampleIntoTheTree() {
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("run.athlos"))));
    window.project()->setModified(false);

    ProcessorDialog dialog(window);
    QVERIFY(dialog.selectProcessor(QStringLiteral("resample")));
    QComboBox* input = dialog.inputBox(0);
    QVERIFY(input);
    input->setCurrentIndex(input->findData(QStringLiteral("run1/imu")));
    QCOMPARE(dialog.outputEdit()->text(), QStringLiteral("run1/imu-resample"));
    dialog.outputEdit()->setText(QStringLiteral("run1/imu-50hz"));
    qobject_cast<QDoubleSpinBox*>(dialog.parameterForm()->editor(QStringLiteral("rate")))->setValue(50.0);
    qobject_cast<QComboBox*>(dialog.parameterForm()->editor(QStringLiteral("method")))
        ->setCurrentText(QStringLiteral("cubic"));

    const Status ran = dialog.run();
    QVERIFY2(ran, qPrintable(ran ? QString() : ran.message()));
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    QCOMPARE(dialog.written(), QStringList{QStringLiteral("run1/imu-50hz")});

    const Stream* out = window.project()->stream(QStringLiteral("run1/imu-50hz"));
    QVERIFY(out);
    QCOMPARE(out->info().provenance.processorId, QStringLiteral("resample"));
    QCOMPARE(out->info().provenance.parameters.value(QStringLiteral("rate")).toDouble(), 50.0);
    // 2000 samples at 100 Hz span 19.99 s: 50 Hz gives about 1000.
    QVERIFY(std::abs(out->info().rows - 1000) <= 1);
    QVERIFY(window.treeModel()->indexOf(QStringLiteral("run1/imu-50hz")).isValid());
    QCOMPARE(window.currentItem(), QStringLiteral("run1/imu-50hz"));
    QVERIFY(window.project()->isModified());
    QVERIFY(window.isWindowModified());
    QVERIFY(window.menuBar()->isEnabled());  // not left busy
}

void GuiWorkspaceTest::rerunPrefillsFromProvenance() {
    MainWindow window;
    window.setInteractive(false);
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("rerun.athlos"))));
    RunRequest first{QStringLiteral("resample"),
                     {QStringLiteral("run1/imu")},
                     QStringLiteral("run1/imu-rs"),
                     {{QStringLiteral("rate"), 25.0}, {QStringLiteral("method"), QStringLiteral("nearest")}}};
    auto outcome = window.runProcessor(first);
    QVERIFY2(outcome, qPrintable(outcome ? QString() : outcome.message()));

    QVERIFY(window.rerunRequest(QStringLiteral("run1/imu")).processorId.isEmpty());  // an import, not a result
    const RunRequest rerun = window.rerunRequest(QStringLiteral("run1/imu-rs"));
    QCOMPARE(rerun.processorId, QStringLiteral("resample"));
    QCOMPARE(rerun.inputs, QStringList{QStringLiteral("run1/imu")});
    QCOMPARE(rerun.output, QStringLiteral("run1/imu-rs"));

    ProcessorDialog dialog(window);
    QVERIFY(dialog.setRequest(rerun));
    QCOMPARE(dialog.processorId(), QStringLiteral("resample"));
    QCOMPARE(dialog.inputBox(0)->currentData().toString(), QStringLiteral("run1/imu"));
    QCOMPARE(dialog.outputEdit()->text(), QStringLiteral("run1/imu-rs"));
    auto* rate = qobject_cast<QDoubleSpinBox*>(dialog.parameterForm()->editor(QStringLiteral("rate")));
    QCOMPARE(rate->value(), 25.0);
    QCOMPARE(qobject_cast<QComboBox*>(dialog.parameterForm()->editor(QStringLiteral("method")))->currentText(),
             QStringLiteral("nearest"));

    // Changed parameter, same output: the result is replaced.
    rate->setValue(10.0);
    const Status ran = dialog.run();
    QVERIFY2(ran, qPrintable(ran ? QString() : ran.message()));
    const Stream* out = window.project()->stream(QStringLiteral("run1/imu-rs"));
    QCOMPARE(out->info().provenance.parameters.value(QStringLiteral("rate")).toDouble(), 10.0);
    QVERIFY(std::abs(out->info().rows - 200) <= 1);
}

void GuiWorkspaceTest::invalidParametersStayInTheDialog() {
    MainWindow window;
    window.setInteractive(false);
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("invalid.athlos"))));
    ProcessorDialog dialog(window);
    QVERIFY(dialog.selectProcessor(QStringLiteral("resample")));
    dialog.outputEdit()->setText(QStringLiteral("no-slash"));
    QVERIFY(!dialog.run());
    QVERIFY(dialog.errorText().contains(QStringLiteral("recording/name")));
    dialog.outputEdit()->setText(QStringLiteral("run1/x"));
    // rate stays 0: the processor refuses it and nothing is written.
    QVERIFY(!dialog.run());
    QVERIFY(!dialog.errorText().isEmpty());
    QVERIFY(!window.project()->stream(QStringLiteral("run1/x")));
    QCOMPARE(dialog.result(), int(QDialog::Rejected));
}

QTEST_MAIN(GuiWorkspaceTest)
#include "GuiWorkspaceTest.moc"
