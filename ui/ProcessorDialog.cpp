#include "ui/ProcessorDialog.h"

#include "core/model/Project.h"
#include "core/processing/ProcessorRegistry.h"
#include "ui/ParameterForm.h"
#include "ui/Workspace.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace athlos::ui {

namespace {

// Streams (or tables) of the project that the input accepts.
QStringList candidates(const Project* project, const InputSpec& spec) {
    QStringList paths;
    if (!project) return paths;
    if (spec.table) {
        for (const QString& path : project->tablePaths()) {
            const Table* table = project->table(path);
            if (spec.kinds.isEmpty() || (table && spec.kinds.contains(table->kind))) paths << path;
        }
    } else {
        for (const QString& path : project->streamPaths()) {
            const Stream* stream = project->stream(path);
            if (spec.kinds.isEmpty() || (stream && spec.kinds.contains(stream->kind()))) paths << path;
        }
    }
    return paths;
}

}  // namespace

ProcessorDialog::ProcessorDialog(Workspace& workspace, QWidget* parent) : QDialog(parent), workspace_(workspace) {
    setWindowTitle(tr("Run Processor"));

    processorBox_ = new QComboBox(this);
    const ProcessorRegistry& registry = ProcessorRegistry::instance();
    for (const QString& id : registry.ids()) {
        const auto processor = registry.find(id);
        processorBox_->addItem(QStringLiteral("%1 (%2)").arg(processor->name(), id), id);
    }
    description_ = new QLabel(this);
    description_->setWordWrap(true);

    auto* inputsGroup = new QGroupBox(tr("Inputs and output"), this);
    inputsLayout_ = new QFormLayout;
    auto* outputLayout = new QFormLayout;
    auto* inputsGroupLayout = new QVBoxLayout(inputsGroup);
    inputsGroupLayout->addLayout(inputsLayout_);
    inputsGroupLayout->addLayout(outputLayout);
    outputEdit_ = new QLineEdit(this);
    outputLayout->addRow(tr("Output:"), outputEdit_);
    outputEdit_->setPlaceholderText(tr("recording/name"));
    outputEdit_->setToolTip(tr("Where the result is stored, as recording/name"));
    connect(outputEdit_, &QLineEdit::textEdited, this, [this] { outputEdited_ = true; });

    auto* paramsGroup = new QGroupBox(tr("Parameters"), this);
    form_ = new ParameterForm(paramsGroup);
    auto* scroll = new QScrollArea(paramsGroup);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(form_);
    auto* paramsLayout = new QVBoxLayout(paramsGroup);
    paramsLayout->addWidget(scroll);

    error_ = new QLabel(this);
    error_->setWordWrap(true);
    error_->setStyleSheet(QStringLiteral("color: #b00020;"));
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_->hide();

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton* runButton = buttons->addButton(tr("Run"), QDialogButtonBox::AcceptRole);
    runButton->setDefault(true);
    runButton->setEnabled(processorBox_->count() > 0);
    // Not accept() directly: the dialog stays open with the error when the run fails.
    connect(runButton, &QPushButton::clicked, this, [this] { (void)run(); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    top->addRow(tr("Processor:"), processorBox_);
    layout->addLayout(top);
    layout->addWidget(description_);
    layout->addWidget(inputsGroup);
    layout->addWidget(paramsGroup, 1);
    layout->addWidget(error_);
    layout->addWidget(buttons);

    connect(processorBox_, &QComboBox::currentIndexChanged, this, &ProcessorDialog::onProcessorChanged);
    if (processorBox_->count() == 0)
        showError(tr("No processors were found. Check the plugin folder (ATHLOS_PLUGIN_PATH)."));
    onProcessorChanged();
    resize(560, 600);
}

QString ProcessorDialog::processorId() const { return processorBox_->currentData().toString(); }

bool ProcessorDialog::selectProcessor(const QString& id) {
    const int index = processorBox_->findData(id);
    if (index < 0) return false;
    processorBox_->setCurrentIndex(index);
    return true;
}

void ProcessorDialog::onProcessorChanged() {
    // removeRow deletes the label and the combo box of each input.
    inputBoxes_.clear();
    while (inputsLayout_->rowCount() > 0) inputsLayout_->removeRow(0);

    const auto processor = ProcessorRegistry::instance().find(processorId());
    if (!processor) {
        form_->setSpecs({});
        description_->clear();
        return;
    }
    description_->setText(processor->description());
    for (const InputSpec& spec : processor->inputs()) {
        auto* box = new QComboBox(this);
        box->setToolTip(spec.help);
        if (spec.optional) box->addItem(tr("(none)"), QString());
        for (const QString& path : candidates(workspace_.project(), spec)) box->addItem(path, path);
        connect(box, &QComboBox::currentIndexChanged, this, &ProcessorDialog::suggestOutput);
        QString label = spec.name;
        if (!spec.kinds.isEmpty()) label += QStringLiteral(" (%1)").arg(spec.kinds.join(QStringLiteral(", ")));
        inputsLayout_->addRow(label + QLatin1Char(':'), box);
        inputBoxes_ << box;
    }
    form_->setSpecs(processor->parameters());
    error_->hide();
    suggestOutput();
}

void ProcessorDialog::suggestOutput() {
    if (outputEdited_) return;
    const QString first = inputBoxes_.isEmpty() ? QString() : inputBoxes_.front()->currentData().toString();
    outputEdit_->setText(first.isEmpty() ? QString() : first + QLatin1Char('-') + processorId());
}

bool ProcessorDialog::setRequest(const RunRequest& request) {
    if (!selectProcessor(request.processorId)) return false;
    for (int i = 0; i < inputBoxes_.size() && i < request.inputs.size(); ++i) {
        QComboBox* box = inputBoxes_[i];
        int index = box->findData(request.inputs[i]);
        if (index < 0 && !request.inputs[i].isEmpty()) {
            // A provenance input that is no longer of an accepted kind (or gone) stays visible.
            box->addItem(request.inputs[i], request.inputs[i]);
            index = box->count() - 1;
        }
        if (index >= 0) box->setCurrentIndex(index);
    }
    outputEdit_->setText(request.output);
    outputEdited_ = !request.output.isEmpty();
    form_->setValues(request.parameters);
    return true;
}

RunRequest ProcessorDialog::request() const {
    RunRequest request;
    request.processorId = processorId();
    for (QComboBox* box : inputBoxes_) request.inputs << box->currentData().toString();
    request.output = outputEdit_->text().trimmed();
    request.parameters = form_->values();
    return request;
}

QString ProcessorDialog::errorText() const { return error_->isHidden() ? QString() : error_->text(); }

void ProcessorDialog::showError(const QString& message) {
    error_->setText(message);
    error_->setVisible(!message.isEmpty());
}

Status ProcessorDialog::validate() {
    const auto processor = ProcessorRegistry::instance().find(processorId());
    Status status;
    if (!processor) {
        status = makeError(tr("Choose a processor."));
    } else if (!workspace_.project()) {
        status = makeError(tr("Open a project first."));
    } else if (!ItemPath::parse(request().output).isValid()) {
        status = makeError(tr("The output name must be recording/name, e.g. run1/imu-100hz."));
    } else {
        const QList<InputSpec> specs = processor->inputs();
        for (int i = 0; i < specs.size() && i < inputBoxes_.size(); ++i)
            if (!specs[i].optional && inputBoxes_[i]->currentData().toString().isEmpty()) {
                status = makeError(tr("Input '%1' needs a stream of kind %2; the project has none.")
                                       .arg(specs[i].name, specs[i].kinds.join(QStringLiteral(", "))));
                break;
            }
        if (status) {
            auto params = validateParameters(processor->parameters(), form_->values());
            if (!params) status = params.error();
        }
    }
    showError(status ? QString() : status.message());
    return status;
}

Status ProcessorDialog::run() {
    if (Status valid = validate(); !valid) return valid;
    auto outcome = workspace_.runProcessor(request());
    if (!outcome) {
        showError(outcome.message());
        return outcome.error();
    }
    written_ = outcome->written;
    accept();
    return {};
}

}  // namespace athlos::ui
