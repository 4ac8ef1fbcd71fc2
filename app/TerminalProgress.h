#pragma once
// Progress bar on the terminal and Ctrl-C cancellation for long CLI runs.
// The bar is drawn only when stderr is a terminal (CI logs stay clean); the first Ctrl-C asks the
// running job to stop (it then leaves the project untouched), a second one exits at once.
#include "core/util/Progress.h"

#include <QElapsedTimer>
#include <QString>

namespace athlos::cli {

class TerminalProgress {
public:
    explicit TerminalProgress(QString label);
    ~TerminalProgress();
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    // A Progress wired to this bar and to Ctrl-C.
    Progress progress();
    void finish();

private:
    void draw(double fraction, const QString& message);

    QString label_;
    bool enabled_;
    bool drawn_ = false;
    QElapsedTimer sinceDraw_;
};

}  // namespace athlos::cli
