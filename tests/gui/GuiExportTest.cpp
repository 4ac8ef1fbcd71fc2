// Plot export: PNG (device pixel ratio applied), SVG and PDF files with real content, unknown
// formats refused; the plot style follows a dark palette.
#include "GuiTestSupport.h"
#include "ui/MainWindow.h"
#include "ui/PlotExporter.h"
#include "ui/PlotStyle.h"
#include "ui/TimeSeriesPanel.h"

#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

using namespace athlos;
using namespace athlos::ui;

class GuiExportTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void writesPngSvgPdf();
    void followsDarkPalette();

private:
    QTemporaryDir dir_;
};

void GuiExportTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
}

void GuiExportTest::writesPngSvgPdf() {
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("export.athlos"))));
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    window.waitForPlots();
    QCustomPlot* plot = window.timeSeriesPanel()->plot();

    const QString png = dir_.filePath(QStringLiteral("plot.png"));
    QVERIFY(PlotExporter::exportPlot(plot, png, QSize(640, 400), 2.0));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1280, 800));  // 2× device pixels
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    QVERIFY2(colours.size() > 20, qPrintable(QString::number(colours.size())));

    const QString svg = dir_.filePath(QStringLiteral("plot.svg"));
    QVERIFY(PlotExporter::exportPlot(plot, svg));
    QFile svgFile(svg);
    QVERIFY(svgFile.open(QIODevice::ReadOnly));
    const QByteArray svgText = svgFile.readAll();
    QVERIFY(svgText.contains("<svg"));
    QVERIFY(svgText.contains("polyline") || svgText.contains("<path"));
    QVERIFY(svgText.size() > 5000);

    const QString pdf = dir_.filePath(QStringLiteral("plot.pdf"));
    QVERIFY(PlotExporter::exportPlot(plot, pdf));
    QFile pdfFile(pdf);
    QVERIFY(pdfFile.open(QIODevice::ReadOnly));
    QVERIFY(pdfFile.read(5) == "%PDF-");
    QVERIFY(pdfFile.size() > 2000);

    const Status unknown = PlotExporter::exportPlot(plot, dir_.filePath(QStringLiteral("plot.bmpx")));
    QVERIFY(!unknown);
    QVERIFY(unknown.message().contains(QStringLiteral("bmpx")));
}

void GuiExportTest::followsDarkPalette() {
    QCustomPlot plot;
    PlotStyle::apply(&plot);
    QPalette dark = plot.palette();
    dark.setColor(QPalette::Base, QColor(30, 30, 30));
    dark.setColor(QPalette::Text, QColor(230, 230, 230));
    plot.setPalette(dark);  // PaletteChange: the plot re-styles itself
    QCOMPARE(plot.xAxis->tickLabelColor(), QColor(230, 230, 230));
    const QImage image = plot.toPixmap(200, 100).toImage();
    QVERIFY(QColor(image.pixel(2, 2)).lightness() < 60);
}

QTEST_MAIN(GuiExportTest)
#include "GuiExportTest.moc"
