// `athlos screenshot`'s renderer: exactly 1280×800, and the plot area really shows a plot.
#include "GuiTestSupport.h"
#include "ui/UiEntry.h"

#include <QImage>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

using namespace athlos;

namespace {

// Saturated pixels in the given region: the data colours, as opposed to the grey/white chrome.
int colouredPixels(const QImage& image, const QRect& region) {
    int count = 0;
    for (int y = region.top(); y <= region.bottom(); ++y)
        for (int x = region.left(); x <= region.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.hsvSaturation() > 100 && c.value() > 60) ++count;
        }
    return count;
}

int distinctColours(const QImage& image) {
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

}  // namespace

class GuiScreenshotTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void mainViewShowsThePlot();
    void trajectoryViewShowsThePath();
    void trajectoryFallsBackWithoutPositions();
    void refusesUnknownViewsAndMissingProjects();

private:
    QTemporaryDir dir_;
    QString project_;
};

void GuiScreenshotTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
    project_ = dir_.filePath(QStringLiteral("shot.athlos"));
    auto project = testing::makeProject(project_);
    const Status saved = project->save();
    QVERIFY2(saved.ok(), saved.ok() ? "" : qPrintable(saved.message()));
}

void GuiScreenshotTest::mainViewShowsThePlot() {
    const QString png = dir_.filePath(QStringLiteral("main.png"));
    const Status s = ui::renderScreenshot(project_, QStringLiteral("main"), png);
    QVERIFY2(s.ok(), s.ok() ? "" : qPrintable(s.message()));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1280, 800));
    QVERIFY2(distinctColours(image) > 50, qPrintable(QString::number(distinctColours(image))));
    // The right part of the window is the plot (the project tree docks on the left).
    const int plotted = colouredPixels(image, QRect(500, 120, 740, 560));
    QVERIFY2(plotted > 2000, qPrintable(QString::number(plotted)));
    QCOMPARE(colouredPixels(image, QRect(0, 0, 1280, 800)) > plotted - 1, true);
}

void GuiScreenshotTest::trajectoryViewShowsThePath() {
    const QString png = dir_.filePath(QStringLiteral("trajectory.png"));
    const Status s = ui::renderScreenshot(project_, QStringLiteral("trajectory"), png, QSize(1280, 800));
    QVERIFY2(s.ok(), s.ok() ? "" : qPrintable(s.message()));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1280, 800));
    const int plotted = colouredPixels(image, QRect(500, 120, 740, 560));
    QVERIFY2(plotted > 800, qPrintable(QString::number(plotted)));
}

void GuiScreenshotTest::trajectoryFallsBackWithoutPositions() {
    const QString path = dir_.filePath(QStringLiteral("imu-only.athlos"));
    auto project = Project::create(path);
    project->putStream(QStringLiteral("run/imu"), testing::makeImuStream());
    QVERIFY(project->save().ok());
    const QString png = dir_.filePath(QStringLiteral("fallback.png"));
    const Status s = ui::renderScreenshot(path, QStringLiteral("trajectory"), png);
    QVERIFY2(s.ok(), s.ok() ? "" : qPrintable(s.message()));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1280, 800));
    QVERIFY(colouredPixels(image, QRect(500, 120, 740, 560)) > 2000);  // the IMU time series instead
}

void GuiScreenshotTest::refusesUnknownViewsAndMissingProjects() {
    // Built-in views first; tools add theirs after (ATHLOS_REGISTER_VIEW).
    QCOMPARE(ui::screenshotViews().mid(0, 3),
             QStringList({QStringLiteral("main"), QStringLiteral("trajectory"), QStringLiteral("annotate")}));
    const QString png = dir_.filePath(QStringLiteral("never.png"));
    const Status unknown = ui::renderScreenshot(project_, QStringLiteral("3d"), png);
    QVERIFY(!unknown.ok());
    QVERIFY2(unknown.message().contains(QStringLiteral("3d")) &&
                 unknown.message().contains(QStringLiteral("main, trajectory")),
             qPrintable(unknown.message()));
    const Status missing =
        ui::renderScreenshot(dir_.filePath(QStringLiteral("missing.athlos")), QStringLiteral("main"), png);
    QVERIFY(!missing.ok());
    QVERIFY2(missing.message().contains(QStringLiteral("missing.athlos")), qPrintable(missing.message()));
    QVERIFY(!QFileInfo::exists(png));
}

QTEST_MAIN(GuiScreenshotTest)
#include "GuiScreenshotTest.moc"
