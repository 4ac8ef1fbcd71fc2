// `athlos screenshot` views beyond main/trajectory: every view in screenshotViews() renders
// 1280×800 with data (built-in ones must succeed; registered ones may refuse a project without
// their data, but then with a message), and `annotate` shows spans, cursor and the class list.
#include "GuiTestSupport.h"
#include "ui/PlotStyle.h"
#include "ui/ToolRegistry.h"
#include "ui/UiEntry.h"

#include <QImage>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

using namespace athlos;

namespace {

int distinctColours(const QImage& image, const QRect& region) {
    QSet<QRgb> colours;
    for (int y = region.top(); y <= region.bottom(); y += 2)
        for (int x = region.left(); x <= region.right(); x += 2) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

// Pixels close to a colour (the annotation spans are translucent class colours over white).
int pixelsNear(const QImage& image, QColor colour, int tolerance) {
    int count = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                    std::abs(c.blue() - colour.blue()) <=
                tolerance)
                ++count;
        }
    return count;
}

}  // namespace

class GuiViewsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void everyViewRenders();
    void annotateShowsSpansAndClasses();
    void viewsWithoutDataFailClearly();

private:
    QTemporaryDir dir_;
    QString project_;
};

void GuiViewsTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
    project_ = dir_.filePath(QStringLiteral("views.athlos"));
    auto project = testing::makeProject(project_);
    project->annotationClasses() = {QStringLiteral("stance"), QStringLiteral("swing")};
    Annotations& list = project->recording(QStringLiteral("run1"))->annotations;
    list.push_back({QStringLiteral("stance"), 2.0, 6.0, QStringLiteral("a"), 1.0, QStringLiteral("manual")});
    list.push_back({QStringLiteral("swing"), 9.0, 14.0, {}, 0.7, QStringLiteral("detector")});
    QVERIFY(project->save());
}

void GuiViewsTest::everyViewRenders() {
    const QStringList views = ui::screenshotViews();
    QCOMPARE(views.mid(0, 3),
             (QStringList{QStringLiteral("main"), QStringLiteral("trajectory"), QStringLiteral("annotate")}));
    for (const ui::ViewEntry& entry : ui::registeredViews()) QVERIFY(views.contains(entry.name));
    QCOMPARE(QSet<QString>(views.begin(), views.end()).size(), views.size());
    // ATHLOS_KEEP_SCREENSHOTS=<dir> keeps the pictures for a look.
    const QString keep = qEnvironmentVariable("ATHLOS_KEEP_SCREENSHOTS");
    for (const QString& view : views) {
        const QString png = (keep.isEmpty() ? dir_.path() : keep) + QStringLiteral("/%1.png").arg(view);
        const Status s = ui::renderScreenshot(project_, view, png);
        const bool builtIn = views.indexOf(view) < 3;
        if (!s) {
            // A registered view may need data this project lacks; it must say so.
            QVERIFY2(!builtIn, qPrintable(view + QStringLiteral(": ") + s.message()));
            QVERIFY2(s.message().size() > 10, qPrintable(view));
            qInfo("view %s refused: %s", qPrintable(view), qPrintable(s.message()));
            continue;
        }
        const QImage image(png);
        QCOMPARE(image.size(), QSize(1280, 800));
        const int colours = distinctColours(image, QRect(400, 100, 860, 650));
        QVERIFY2(colours > 40, qPrintable(QStringLiteral("%1: %2 colours").arg(view).arg(colours)));
    }
}

void GuiViewsTest::annotateShowsSpansAndClasses() {
    const QString png = dir_.filePath(QStringLiteral("annotate-check.png"));
    const Status s = ui::renderScreenshot(project_, QStringLiteral("annotate"), png);
    QVERIFY2(s, qPrintable(s ? QString() : s.message()));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1280, 800));
    // The "stance" span: the colour of class 0 at alpha 70 over the white plot.
    const QColor stance = ui::PlotStyle::seriesColor(0);
    const QColor blended((stance.red() * 70 + 255 * 185) / 255, (stance.green() * 70 + 255 * 185) / 255,
                         (stance.blue() * 70 + 255 * 185) / 255);
    const int spanPixels = pixelsNear(image, blended, 24);
    QVERIFY2(spanPixels > 500, qPrintable(QString::number(spanPixels)));

    // Also without any annotations the view renders (the class list and an empty table show).
    const QString bare = dir_.filePath(QStringLiteral("bare.athlos"));
    auto project = testing::makeProject(bare);
    QVERIFY(project->save());
    const Status plain =
        ui::renderScreenshot(bare, QStringLiteral("annotate"), dir_.filePath(QStringLiteral("bare.png")));
    QVERIFY2(plain, qPrintable(plain ? QString() : plain.message()));
}

void GuiViewsTest::viewsWithoutDataFailClearly() {
    const QString empty = dir_.filePath(QStringLiteral("empty.athlos"));
    QVERIFY(Project::create(empty)->save());
    for (const QString& view : {QStringLiteral("main"), QStringLiteral("annotate")}) {
        const QString png = dir_.filePath(QStringLiteral("empty-%1.png").arg(view));
        const Status s = ui::renderScreenshot(empty, view, png);
        QVERIFY2(!s, qPrintable(view));
        QVERIFY2(s.message().contains(QStringLiteral("stream")), qPrintable(s.message()));
        QVERIFY(!QFileInfo::exists(png));
    }
}

QTEST_MAIN(GuiViewsTest)
#include "GuiViewsTest.moc"
