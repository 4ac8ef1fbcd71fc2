#include "ui/PlotExporter.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QSvgGenerator>
#include <qcustomplot.h>

namespace athlos::ui {

namespace {
const QString kDirKey = QStringLiteral("export/directory");
const QString kFilterKey = QStringLiteral("export/filter");
}  // namespace

Status PlotExporter::exportPlot(QCustomPlot* plot, const QString& path, QSize size, double scale) {
    if (!plot) return makeError(tr("Nothing to export."));
    if (size.isEmpty()) size = plot->size();
    const QString suffix = QFileInfo(path).suffix().toLower();
    bool ok = false;
    if (suffix == QLatin1String("png")) {
        if (scale <= 0) scale = plot->devicePixelRatioF();
        ok = plot->savePng(path, size.width(), size.height(), scale);
    } else if (suffix == QLatin1String("pdf")) {
        ok = plot->savePdf(path, size.width(), size.height());
    } else if (suffix == QLatin1String("svg")) {
        QSvgGenerator generator;
        generator.setFileName(path);
        generator.setSize(size);
        generator.setViewBox(QRect(QPoint(0, 0), size));
        generator.setTitle(plot->windowTitle());
        QCPPainter painter;
        ok = painter.begin(&generator);
        if (ok) {
            plot->toPainter(&painter, size.width(), size.height());
            ok = painter.end();
        }
        ok = ok && QFileInfo(path).size() > 0;
    } else {
        return makeError(tr("Unknown export format '%1'; use .png, .svg or .pdf.").arg(suffix));
    }
    if (!ok) return makeError(tr("Could not write %1.").arg(QDir::toNativeSeparators(path)));
    return {};
}

QString PlotExporter::exportDialog(QCustomPlot* plot, QWidget* parent) {
    QSettings settings;
    const QStringList filters{tr("PNG image (*.png)"), tr("SVG drawing (*.svg)"), tr("PDF document (*.pdf)")};
    QString filter = settings.value(kFilterKey, filters.front()).toString();
    if (!filters.contains(filter)) filter = filters.front();
    const QString dir = settings.value(kDirKey, QDir::homePath()).toString();
    QString path =
        QFileDialog::getSaveFileName(parent, tr("Export View"), dir, filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty()) return {};
    if (QFileInfo(path).suffix().isEmpty())
        path +=
            QStringLiteral(".") + QStringList{QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")}.at(
                                      std::max<qsizetype>(0, filters.indexOf(filter)));
    settings.setValue(kDirKey, QFileInfo(path).absolutePath());
    settings.setValue(kFilterKey, filter);
    const Status status = exportPlot(plot, path);
    if (!status) {
        QMessageBox::critical(parent, tr("Export View"), status.message());
        return {};
    }
    return path;
}

}  // namespace athlos::ui
