#include "ui/wizards/ImportWizardMappingPage.h"

#include "core/io/Importer.h"
#include "core/model/StreamKinds.h"
#include "ui/wizards/ImportWizard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace athlos::ui {
namespace {

// Units offered in the combos (any other can be typed); see core/util/Units for all spellings.
const QStringList& unitChoices() {
    static const QStringList units{QString(), "s",     "ms", "us", "min",   "m",     "mm",   "cm",  "km",  "m/s",
                                   "km/h",    "m/s^2", "g",  "mg", "rad/s", "deg/s", "rpm",  "rad", "deg", "uT",
                                   "nT",      "mT",    "G",  "mG", "1",     "%",     "degC", "K",   "Hz"};
    return units;
}

QComboBox* makeUnitCombo(QWidget* parent, const QString& unit) {
    auto* combo = new QComboBox(parent);
    combo->setEditable(true);
    combo->addItems(unitChoices());
    combo->setCurrentText(unit);
    return combo;
}

// The time column's unit or format (core/io/TimeFormats.h; any other spelling can be typed).
const QStringList& timeFormatChoices() {
    static const QStringList formats{QString(), "s",       "ms",        "us",        "ns",           "min",  "h",
                                     "d",       "uptime",  "uptime_ms", "uptime_us", "uptime_ns",    "unix", "unix_ms",
                                     "unix_us", "unix_ns", "iso",       "hh:mm:ss",  "hh:mm:ss.fff", "excel"};
    return formats;
}

QString labelNamesText(const std::map<QString, QString>& names) {
    QStringList pairs;
    for (const auto& [value, name] : names) pairs << value + QLatin1Char('=') + name;
    return pairs.join(QLatin1Char(','));
}

const ColumnMapping* findMapping(const ImportOptions& options, const QString& source) {
    for (const ColumnMapping& m : options.columns)
        if (m.source == source) return &m;
    return nullptr;
}

}  // namespace

ImportWizardMappingPage::ImportWizardMappingPage(ImportWizard& wizard) : wizard_(wizard) {
    setTitle(tr("Columns and Names"));
    setSubTitle(
        tr("Check each file: format, kind, the first rows, and which channel and unit each column becomes. "
           "Values are converted to SI units when imported."));
    auto* layout = new QVBoxLayout(this);

    auto* top = new QFormLayout;
    fileCombo_ = new QComboBox(this);
    fileCombo_->setObjectName(QStringLiteral("fileCombo"));
    top->addRow(tr("File:"), fileCombo_);
    auto* kindRow = new QHBoxLayout;
    formatCombo_ = new QComboBox(this);
    formatCombo_->setObjectName(QStringLiteral("formatCombo"));
    formatCombo_->addItem(tr("detect"), QStringLiteral("auto"));
    for (const auto& importer : importers()) formatCombo_->addItem(importer->format(), importer->format());
    kindCombo_ = new QComboBox(this);
    kindCombo_->setObjectName(QStringLiteral("kindCombo"));
    kindCombo_->addItem(tr("detect"), QString());
    for (const QString& kind : streamKindNames()) kindCombo_->addItem(kind, kind);
    kindRow->addWidget(new QLabel(tr("Format:"), this));
    kindRow->addWidget(formatCombo_);
    kindRow->addWidget(new QLabel(tr("Kind:"), this));
    kindRow->addWidget(kindCombo_);
    kindRow->addStretch();
    top->addRow(kindRow);
    errorLabel_ = new QLabel(this);
    errorLabel_->setObjectName(QStringLiteral("previewErrorLabel"));
    errorLabel_->setWordWrap(true);
    errorLabel_->setStyleSheet(QStringLiteral("color: #b00020"));
    top->addRow(errorLabel_);
    layout->addLayout(top);

    auto* splitter = new QSplitter(Qt::Vertical, this);
    previewTable_ = new QTableWidget(splitter);
    previewTable_->setObjectName(QStringLiteral("previewTable"));
    previewTable_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    mappingTable_ = new QTableWidget(0, 5, splitter);
    mappingTable_->setObjectName(QStringLiteral("mappingTable"));
    mappingTable_->setHorizontalHeaderLabels(
        {tr("Column"), tr("Channel"), tr("Unit in File"), tr("Stored as"), tr("Import")});
    mappingTable_->horizontalHeader()->setSectionResizeMode(ChannelColumn, QHeaderView::Stretch);
    mappingTable_->verticalHeader()->hide();
    layout->addWidget(splitter, 1);

    auto* names = new QFormLayout;
    auto* timeRow = new QHBoxLayout;
    timeColumnCombo_ = new QComboBox(this);
    timeColumnCombo_->setObjectName(QStringLiteral("timeColumnCombo"));
    timeUnitCombo_ = new QComboBox(this);
    timeUnitCombo_->setEditable(true);
    timeUnitCombo_->addItems(timeFormatChoices());
    timeUnitCombo_->setObjectName(QStringLiteral("timeUnitCombo"));
    timeUnitCombo_->setToolTip(
        tr("Durations (s, ms, …), device uptime, Unix epochs (unix, unix_ms, unix_ns), "
           "ISO 8601 date-times, clock times (hh:mm:ss[.fff]) or Excel serial days"));
    timeRow->addWidget(timeColumnCombo_, 1);
    timeRow->addWidget(new QLabel(tr("Unit or format:"), this));
    timeRow->addWidget(timeUnitCombo_);
    names->addRow(tr("Time column:"), timeRow);
    auto* whenRow = new QHBoxLayout;
    dateEdit_ = new QLineEdit(this);
    dateEdit_->setObjectName(QStringLiteral("dateEdit"));
    dateEdit_->setPlaceholderText(tr("YYYY-MM-DD, for clock times without a date"));
    startEdit_ = new QLineEdit(this);
    startEdit_->setObjectName(QStringLiteral("startEdit"));
    startEdit_->setPlaceholderText(tr("ISO 8601 UTC instant of t = 0, for relative times"));
    whenRow->addWidget(dateEdit_, 1);
    whenRow->addWidget(new QLabel(tr("Start:"), this));
    whenRow->addWidget(startEdit_, 2);
    names->addRow(tr("Date:"), whenRow);
    rateSpin_ = new QDoubleSpinBox(this);
    rateSpin_->setObjectName(QStringLiteral("rateSpin"));
    rateSpin_->setRange(0.0, 100000.0);
    rateSpin_->setDecimals(3);
    rateSpin_->setSuffix(tr(" Hz"));
    rateSpin_->setSpecialValueText(tr("from the motion"));
    rateSpin_->setToolTip(
        tr("gaitmap files whose first column is a sample index: the sampling rate. Left at \"from "
           "the motion\", it is estimated from the foot's rest phases and the import warns with "
           "the candidates' scores (athlos import --rate)"));
    names->addRow(tr("Sampling rate:"), rateSpin_);
    auto* labelRow = new QHBoxLayout;
    labelCombo_ = new QComboBox(this);
    labelCombo_->setObjectName(QStringLiteral("labelCombo"));
    labelCombo_->setToolTip(tr("A per-sample label column (numbers or text): runs of equal labels become annotations"));
    labelNamesEdit_ = new QLineEdit(this);
    labelNamesEdit_->setObjectName(QStringLiteral("labelNamesEdit"));
    labelNamesEdit_->setPlaceholderText(tr("names of number labels: 0=rest,1=run"));
    labelRow->addWidget(labelCombo_, 1);
    labelRow->addWidget(labelNamesEdit_, 2);
    names->addRow(tr("Labels:"), labelRow);
    dropUnmappedBox_ = new QCheckBox(tr("Leave out columns that are neither mapped nor known to the kind"), this);
    dropUnmappedBox_->setObjectName(QStringLiteral("dropUnmappedBox"));
    names->addRow(dropUnmappedBox_);
    recordingEdit_ = new QLineEdit(this);
    recordingEdit_->setObjectName(QStringLiteral("recordingEdit"));
    streamEdit_ = new QLineEdit(this);
    streamEdit_->setObjectName(QStringLiteral("streamEdit"));
    athleteEdit_ = new QLineEdit(this);
    athleteEdit_->setObjectName(QStringLiteral("athleteEdit"));
    names->addRow(tr("Recording:"), recordingEdit_);
    names->addRow(tr("Stream:"), streamEdit_);
    names->addRow(tr("Athlete:"), athleteEdit_);
    layout->addLayout(names);

    connect(fileCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (!loading_) showFile(index);
    });
    connect(mappingTable_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (!loading_ && item->column() == ChannelColumn) updateStored(item->row());
    });
    connect(formatCombo_, &QComboBox::currentIndexChanged, this, &ImportWizardMappingPage::onFormatOrKindChanged);
    connect(kindCombo_, &QComboBox::currentIndexChanged, this, &ImportWizardMappingPage::onFormatOrKindChanged);
    connect(timeColumnCombo_, &QComboBox::currentIndexChanged, this, [this] {
        if (loading_) return;
        store();
        auto& s = wizard_.files()[size_t(current_)];
        const int c = timeColumnCombo_->currentIndex() - 1;  // entry 0: no time column
        s.options.timeUnit =
            c >= 0 && c < int(s.preview.columns.size()) ? s.preview.columns[size_t(c)].unit : QString();
        load();
    });
}

QComboBox* ImportWizardMappingPage::unitCombo(int row) const {
    return qobject_cast<QComboBox*>(mappingTable_->cellWidget(row, UnitColumn));
}

void ImportWizardMappingPage::initializePage() {
    loading_ = true;
    fileCombo_->clear();
    for (const ImportFileSettings& s : wizard_.files()) fileCombo_->addItem(QFileInfo(s.file).fileName());
    loading_ = false;
    current_ = -1;
    showFile(wizard_.files().empty() ? -1 : 0);
}

bool ImportWizardMappingPage::validatePage() {
    store();
    if (labelNamesError_.isEmpty()) return true;
    errorLabel_->setText(labelNamesError_);
    errorLabel_->setVisible(true);
    return false;
}

void ImportWizardMappingPage::showFile(int index) {
    store();
    current_ = index;
    if (fileCombo_->currentIndex() != index) {
        loading_ = true;
        fileCombo_->setCurrentIndex(index);
        loading_ = false;
    }
    load();
}

void ImportWizardMappingPage::onFormatOrKindChanged() {
    if (loading_ || current_ < 0) return;
    store();
    auto& s = wizard_.files()[size_t(current_)];
    s.options.format = formatCombo_->currentData().toString();
    s.options.kind = kindCombo_->currentData().toString();
    wizard_.refreshPreview(current_, true);
    load();
}

void ImportWizardMappingPage::load() {
    loading_ = true;
    previewTable_->clear();
    mappingTable_->setRowCount(0);
    timeColumnCombo_->clear();
    labelCombo_->clear();
    if (current_ < 0 || current_ >= int(wizard_.files().size())) {
        previewTable_->setRowCount(0);
        previewTable_->setColumnCount(0);
        loading_ = false;
        return;
    }
    const ImportFileSettings& s = wizard_.files()[size_t(current_)];
    const ImportPreview& p = s.preview;
    formatCombo_->setCurrentIndex(std::max(0, formatCombo_->findData(s.options.format)));
    kindCombo_->setCurrentIndex(std::max(0, kindCombo_->findData(s.options.kind)));
    errorLabel_->setText(s.previewError);
    errorLabel_->setVisible(!s.previewError.isEmpty());

    QStringList headers;
    for (const PreviewColumn& c : p.columns) headers << c.header;
    previewTable_->setColumnCount(int(headers.size()));
    previewTable_->setHorizontalHeaderLabels(headers);
    previewTable_->setRowCount(int(p.rows.size()));
    QStringList lineLabels;
    for (int r = 0; r < int(p.rows.size()); ++r) {
        lineLabels << (p.mappable ? QString() : QString::number(r + 1));
        for (int c = 0; c < int(p.rows[size_t(r)].size()) && c < int(headers.size()); ++c)
            previewTable_->setItem(r, c, new QTableWidgetItem(p.rows[size_t(r)][c]));
    }
    if (p.mappable) {
        lineLabels.clear();  // csv: label the rows by their line numbers in the file, as errors do
        for (int r = 0; r < int(p.rows.size()); ++r) lineLabels << tr("line %1").arg(p.headerLine + 1 + r);
    }
    previewTable_->setVerticalHeaderLabels(lineLabels);
    previewTable_->resizeColumnsToContents();

    const QString timeSource = s.options.timeColumn.isEmpty() ? QStringLiteral("t") : s.options.timeColumn;
    QString timeUnit = s.options.timeUnit;
    mappingTable_->setRowCount(int(p.columns.size()));
    timeColumnCombo_->addItem(tr("none (a table)"));
    labelCombo_->addItem(tr("none"));
    for (int r = 0; r < int(p.columns.size()); ++r) {
        const PreviewColumn& c = p.columns[size_t(r)];
        const ColumnMapping* m = findMapping(s.options, c.source);
        const bool isTime = p.mappable ? c.source == timeSource : c.time;
        timeColumnCombo_->addItem(c.source);
        labelCombo_->addItem(c.source);
        if (p.mappable && c.source == s.options.labelColumn) labelCombo_->setCurrentIndex(r + 1);
        if (isTime) {
            timeColumnCombo_->setCurrentIndex(r + 1);
            if (timeUnit.isEmpty()) timeUnit = c.unit;
        }
        auto* source = new QTableWidgetItem(c.header);
        source->setFlags(source->flags() & ~Qt::ItemIsEditable);
        mappingTable_->setItem(r, SourceColumn, source);
        auto* channel = new QTableWidgetItem(isTime                       ? QStringLiteral("t")
                                             : m && !m->channel.isEmpty() ? m->channel
                                                                          : c.source);
        if (isTime || !p.mappable) channel->setFlags(channel->flags() & ~Qt::ItemIsEditable);
        mappingTable_->setItem(r, ChannelColumn, channel);
        auto* unit = makeUnitCombo(mappingTable_, m && !m->unit.isEmpty() ? m->unit : c.unit);
        unit->setEnabled(p.mappable && !isTime);
        mappingTable_->setCellWidget(r, UnitColumn, unit);
        connect(unit, &QComboBox::currentTextChanged, this, [this, r] {
            if (!loading_) updateStored(r);
        });
        auto* stored = new QTableWidgetItem;
        stored->setFlags(stored->flags() & ~Qt::ItemIsEditable);
        mappingTable_->setItem(r, StoredColumn, stored);
        auto* import = new QTableWidgetItem;
        import->setFlags(Qt::ItemIsEnabled | (p.mappable && !isTime ? Qt::ItemIsUserCheckable : Qt::NoItemFlags));
        import->setCheckState(m && m->skip ? Qt::Unchecked : Qt::Checked);
        mappingTable_->setItem(r, ImportColumn, import);
    }
    for (int r = 0; r < mappingTable_->rowCount(); ++r) updateStored(r);
    timeColumnCombo_->setEnabled(p.mappable);
    timeUnitCombo_->setEnabled(p.mappable);
    timeUnitCombo_->setCurrentText(timeUnit);
    for (QWidget* w :
         std::initializer_list<QWidget*>{dateEdit_, startEdit_, labelCombo_, labelNamesEdit_, dropUnmappedBox_})
        w->setEnabled(p.mappable);
    dateEdit_->setText(s.options.date);
    startEdit_->setText(s.options.start);
    rateSpin_->setEnabled(s.options.format == QLatin1String("gaitmap"));
    rateSpin_->setValue(s.options.rate);
    labelNamesEdit_->setText(labelNamesText(s.options.labelNames));
    dropUnmappedBox_->setChecked(s.options.dropUnmapped);
    mappingTable_->resizeColumnToContents(SourceColumn);

    recordingEdit_->setText(s.recording);
    streamEdit_->setText(s.stream);
    const StreamKind* kind = findStreamKind(p.kind);
    streamEdit_->setPlaceholderText(kind ? kind->defaultName : p.kind);
    athleteEdit_->setText(s.athlete);
    loading_ = false;
}

void ImportWizardMappingPage::updateStored(int row) {
    if (current_ < 0 || current_ >= int(wizard_.files().size())) return;
    const ImportFileSettings& s = wizard_.files()[size_t(current_)];
    const ImportPreview& p = s.preview;
    QTableWidgetItem* item = mappingTable_->item(row, StoredColumn);
    if (row < 0 || row >= int(p.columns.size()) || !item || !unitCombo(row)) return;
    const PreviewColumn& c = p.columns[size_t(row)];
    const QString unit = unitCombo(row)->currentText().trimmed();
    const QString channel = mappingTable_->item(row, ChannelColumn)->text().trimmed();
    const bool time = channel == QLatin1String("t");
    QString text;
    QString problem;
    if (!p.mappable) {
        text = c.storedUnit;
    } else {
        const StreamKind* kind = findStreamKind(p.kind);
        const bool kindRule = time || (kind && !kind->unitFor(channel).isEmpty());
        if (unit == c.unit && !kindRule) {
            text = c.unit;  // a header unit the kind has no rule for is kept as written
        } else {
            const auto stored = storedUnitFor(p.kind, channel, unit, time);
            if (stored)
                text = *stored;
            else
                problem = stored.message();
        }
    }
    item->setText(problem.isEmpty() ? text : tr("error"));
    item->setToolTip(problem);
    item->setForeground(problem.isEmpty() ? palette().text() : QBrush(QColor(0xb0, 0x00, 0x20)));
}

void ImportWizardMappingPage::store() {
    if (loading_ || current_ < 0 || current_ >= int(wizard_.files().size())) return;
    ImportFileSettings& s = wizard_.files()[size_t(current_)];
    s.recording = recordingEdit_->text().trimmed();
    s.stream = streamEdit_->text().trimmed();
    s.athlete = athleteEdit_->text().trimmed();
    s.options.rate = s.options.format == QLatin1String("gaitmap") ? rateSpin_->value() : 0.0;
    const ImportPreview& p = s.preview;
    if (!p.mappable || mappingTable_->rowCount() != int(p.columns.size())) return;

    const int time = timeColumnCombo_->currentIndex() - 1;  // entry 0: no time column
    const QString timeSource = time >= 0 ? p.columns[size_t(time)].source : QString();
    s.options.timeColumn = timeSource == QLatin1String("t") ? QString() : timeSource;
    s.options.timeUnit = timeUnitCombo_->currentText().trimmed();
    s.options.date = dateEdit_->text().trimmed();
    s.options.start = startEdit_->text().trimmed();
    s.options.dropUnmapped = dropUnmappedBox_->isChecked();
    const int label = labelCombo_->currentIndex() - 1;  // entry 0: none
    s.options.labelColumn = label >= 0 && label < int(p.columns.size()) ? p.columns[size_t(label)].source : QString();
    labelNamesError_.clear();
    if (auto names = parseLabelNames(labelNamesEdit_->text()); !names)
        labelNamesError_ = QFileInfo(s.file).fileName() + QStringLiteral(": ") + names.message();
    else
        s.options.labelNames = std::move(*names);
    s.options.columns.clear();
    for (int r = 0; r < mappingTable_->rowCount(); ++r) {
        const PreviewColumn& c = p.columns[size_t(r)];
        if (r == time || r == label) continue;  // the label column becomes annotations, not a channel
        const QString channel = mappingTable_->item(r, ChannelColumn)->text().trimmed();
        const QString unit = unitCombo(r)->currentText().trimmed();
        if (mappingTable_->item(r, ImportColumn)->checkState() != Qt::Checked)
            s.options.columns.push_back({c.source, {}, {}, true});
        else if ((!channel.isEmpty() && channel != c.source) || unit != c.unit)
            s.options.columns.push_back(
                {c.source, channel == c.source ? QString() : channel, unit == c.unit ? QString() : unit, false});
    }
}

}  // namespace athlos::ui
