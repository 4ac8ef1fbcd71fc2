#pragma once
// Page 2 of the import wizard, per file: format and kind (detected), the first rows, the mapping of
// each source column to a channel and the unit its values are in (auto-filled from the header and
// common export names), the time column and its format (durations, epochs, ISO, clock times, Excel
// days; a date or start instant for relative times), a label column that becomes annotations, and
// recording, stream and athlete names.
#include <QWizardPage>

class QCheckBox;
class QComboBox;
class QLabel;
class QDoubleSpinBox;
class QLineEdit;
class QTableWidget;

namespace athlos::ui {

class ImportWizard;

class ImportWizardMappingPage : public QWizardPage {
    Q_OBJECT

public:
    enum MappingColumn { SourceColumn, ChannelColumn, UnitColumn, StoredColumn, ImportColumn };

    explicit ImportWizardMappingPage(ImportWizard& wizard);
    void initializePage() override;
    bool validatePage() override;

    // Shows file index (storing the edits of the file shown so far).
    void showFile(int index);
    // Writes the widgets into the wizard's settings of the file shown.
    void store();

    QTableWidget* previewTable() const { return previewTable_; }
    QTableWidget* mappingTable() const { return mappingTable_; }
    QComboBox* unitCombo(int row) const;

private:
    void load();
    void updateStored(int row);  // the "Stored as" cell of row, from its channel and unit
    void onFormatOrKindChanged();

    ImportWizard& wizard_;
    int current_ = -1;
    bool loading_ = false;
    QComboBox* fileCombo_ = nullptr;
    QComboBox* formatCombo_ = nullptr;
    QComboBox* kindCombo_ = nullptr;
    QLabel* errorLabel_ = nullptr;
    QTableWidget* previewTable_ = nullptr;
    QTableWidget* mappingTable_ = nullptr;
    QComboBox* timeColumnCombo_ = nullptr;
    QComboBox* timeUnitCombo_ = nullptr;
    QLineEdit* recordingEdit_ = nullptr;
    QLineEdit* streamEdit_ = nullptr;
    QLineEdit* athleteEdit_ = nullptr;
    QLineEdit* dateEdit_ = nullptr;
    QLineEdit* startEdit_ = nullptr;
    QDoubleSpinBox* rateSpin_ = nullptr;  // gaitmap sample-index files: Hz, 0 = from the motion
    QComboBox* labelCombo_ = nullptr;
    QLineEdit* labelNamesEdit_ = nullptr;
    QCheckBox* dropUnmappedBox_ = nullptr;
    QString labelNamesError_;  // the label names as typed are not VALUE=NAME pairs
};

}  // namespace athlos::ui
