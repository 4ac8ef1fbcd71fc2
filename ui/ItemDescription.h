#pragma once
// Human-readable descriptions of project items for the details pane and tooltips. Results
// show their provenance (processor, version, parameters, inputs, app version, time) so a user can
// tell how a number came about without leaving the window.
#include "core/model/Column.h"

#include <QCoreApplication>
#include <QString>

namespace athlos {
class Project;
struct Provenance;
struct Recording;
struct StreamInfo;
struct Table;
}  // namespace athlos

namespace athlos::ui {

class ItemDescription {
    Q_DECLARE_TR_FUNCTIONS(athlos::ui::ItemDescription)

public:
    // A processor result, as opposed to imported or hand-made data.
    static bool isResult(const Provenance& provenance);
    // "acc_x [m/s^2], acc_y [m/s^2], …"
    static QString columnsText(const Columns& columns);
    static QString columnsText(const Table& table);

    static QString projectHtml(const Project& project);
    static QString recordingHtml(const Recording& recording);
    static QString streamHtml(const QString& path, const StreamInfo& info);
    static QString tableHtml(const QString& path, const Table& table);
    static QString provenanceHtml(const Provenance& provenance);
    // Short plain-text tooltip: kind, size and, for results, where they came from.
    static QString streamToolTip(const QString& path, const StreamInfo& info);
    static QString tableToolTip(const QString& path, const Table& table);
};

}  // namespace athlos::ui
