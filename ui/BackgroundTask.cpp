#include "ui/BackgroundTask.h"

#include <QEventLoop>
#include <QFutureWatcher>
#include <QMutex>
#include <QPointer>
#include <QProgressDialog>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace athlos::ui {

namespace {
// Written by the worker, read by a GUI timer: the worker never touches widgets and reports as
// often as it likes without flooding the event queue.
struct SharedProgress {
    std::atomic<int> permille{0};
    QMutex mutex;
    QString message;
};
}  // namespace

BackgroundTask::Outcome BackgroundTask::run(QWidget* parent, const QString& label, const Job& job, bool showDialog) {
    auto shared = std::make_shared<SharedProgress>();
    CancelToken token;
    Progress progress(
        [shared](double fraction, const QString& message) {
            if (std::isfinite(fraction)) shared->permille.store(int(std::clamp(fraction, 0.0, 1.0) * 1000));
            if (!message.isEmpty()) {
                QMutexLocker lock(&shared->mutex);
                shared->message = message;
            }
        },
        token);

    QFuture<Status> future = QtConcurrent::run([job, progress] { return job(progress); });
    QFutureWatcher<Status> watcher;
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcher<Status>::finished, &loop, &QEventLoop::quit);
    watcher.setFuture(future);

    std::unique_ptr<QProgressDialog> dialog;
    QTimer timer;
    if (showDialog) {
        dialog = std::make_unique<QProgressDialog>(label, tr("Cancel"), 0, 1000, parent);
        dialog->setWindowModality(Qt::WindowModal);
        dialog->setMinimumDuration(400);  // quick jobs finish without a flashing dialog
        dialog->setAutoClose(false);
        dialog->setAutoReset(false);
        dialog->setValue(0);
        QObject::connect(dialog.get(), &QProgressDialog::canceled, [token]() mutable { token.cancel(); });
        QObject::connect(&timer, &QTimer::timeout, [&] {
            dialog->setValue(shared->permille.load());
            QMutexLocker lock(&shared->mutex);
            if (!shared->message.isEmpty()) dialog->setLabelText(label + QLatin1Char('\n') + shared->message);
        });
        timer.start(100);
    }

    if (!future.isFinished()) loop.exec();
    timer.stop();
    if (dialog) dialog->close();

    Outcome outcome;
    outcome.status = future.result();
    outcome.cancelled = token.isCancelled();
    return outcome;
}

BackgroundTask::Outcome BackgroundTask::runHere(QWidget* parent, const QString& label, const Job& job) {
    QProgressDialog dialog(label, tr("Cancel"), 0, 1000, parent);
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(0);
    CancelToken token;
    const Progress progress(
        [&](double fraction, const QString& message) {
            if (std::isfinite(fraction)) dialog.setValue(int(std::clamp(fraction, 0.0, 1.0) * 1000));
            if (!message.isEmpty()) dialog.setLabelText(label + QLatin1Char('\n') + message);
            QCoreApplication::processEvents();
            if (dialog.wasCanceled()) token.cancel();
        },
        token);
    Outcome outcome;
    outcome.status = job(progress);
    dialog.reset();
    outcome.cancelled = token.isCancelled();
    return outcome;
}

}  // namespace athlos::ui
