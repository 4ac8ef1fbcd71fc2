// German: the embedded .qm loads for ATHLOS_LANG=de and translates the window and the processor
// forms; the .ts in the source tree has a finished translation for every source string.
#include "core/processing/Translator.h"
#include "ui/ItemDescription.h"
#include "ui/MainWindow.h"
#include "ui/UiEntry.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMenuBar>
#include <QXmlStreamReader>
#include <QtTest>

using namespace athlos;
using namespace athlos::ui;

class GuiTranslationTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void translatesKnownStrings();
    void translatesProcessorForms();
    void windowIsGerman();
    void tsFileIsComplete();
};

void GuiTranslationTest::initTestCase() {
    qputenv("ATHLOS_LANG", "de");
    installTranslations(*qApp);
}

void GuiTranslationTest::translatesKnownStrings() {
    QCOMPARE(QCoreApplication::translate("athlos::ui::MainWindow", "&File"), QStringLiteral("&Datei"));
    QCOMPARE(QCoreApplication::translate("athlos::ui::TimeSeriesPanel", "Fit y to visible range"),
             QStringLiteral("y an sichtbaren Bereich anpassen"));
    QCOMPARE(ItemDescription::tr("Provenance"), QStringLiteral("Herkunft"));
    QCOMPARE(QCoreApplication::translate("athlos::ui::UiEntry", "cannot write %1"),
             QStringLiteral("%1 kann nicht geschrieben werden"));
    // Not in the catalogue: unchanged.
    QCOMPARE(QCoreApplication::translate("athlos::ui::MainWindow", "no such string"), QStringLiteral("no such string"));
    // Qt's own strings (standard dialog buttons) come from qtbase_de (qt6-translations-l10n, which
    // scripts/setup.sh installs).
    QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), QStringLiteral("Abbrechen"));
}

// Processor forms: lupdate files a plugin's tr("…") under its processor class when written in a
// member function and under the family namespace when written in a free function; the plugin's
// Translator finds both (core/processing/Translator.h).
void GuiTranslationTest::translatesProcessorForms() {
    const Translator gaitEvents{"athlos::events", "GaitEventsProcessor"};
    QCOMPARE(gaitEvents("Gait events (foot IMU)"), QStringLiteral("Gangereignisse (Fuß-IMU)"));
    const Translator xcCycles{"athlos::events", "XcSkiingCyclesProcessor"};
    QCOMPARE(xcCycles("Sensor axis pointing forward along the ski."),
             QStringLiteral("Sensorachse, die entlang des Skis nach vorn zeigt."));  // a free function's
    const Translator positionFilter{"athlos::positioning", "PositionFilterProcessor"};
    QCOMPARE(positionFilter("Position filter"), QStringLiteral("Positionsfilter"));
    QCOMPARE(positionFilter("no such string"), QStringLiteral("no such string"));
}

void GuiTranslationTest::windowIsGerman() {
    MainWindow window;
    const QList<QAction*> menus = window.menuBar()->actions();
    QVERIFY(menus.size() >= 2);
    QCOMPARE(menus.at(0)->text(), QStringLiteral("&Datei"));
    QCOMPARE(menus.back()->text(), QStringLiteral("&Hilfe"));  // Help stays last
}

void GuiTranslationTest::tsFileIsComplete() {
    QFile file(QStringLiteral(ATHLOS_TEST_DATA_DIR "/../../translations/athlos_de.ts"));
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
    QXmlStreamReader xml(&file);
    int messages = 0;
    QString source;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) continue;
        if (xml.name() == QLatin1String("TS")) {
            QCOMPARE(xml.attributes().value(QLatin1String("language")).toString(), QStringLiteral("de_DE"));
        } else if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            ++messages;
            const bool unfinished = !xml.attributes().value(QLatin1String("type")).isEmpty();
            // Plural messages keep their forms in <numerusform> children.
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            QVERIFY2(!unfinished && !text.trimmed().isEmpty(),
                     qPrintable(QStringLiteral("untranslated: %1").arg(source)));
            // Placeholders must survive translation.
            for (const QString& ph :
                 {QStringLiteral("%1"), QStringLiteral("%2"), QStringLiteral("%3"), QStringLiteral("%n")}) {
                QVERIFY2(source.contains(ph) == text.contains(ph),
                         qPrintable(QStringLiteral("placeholder %1 in: %2").arg(ph, source)));
            }
        }
    }
    QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
    QVERIFY(messages > 50);
}

QTEST_MAIN(GuiTranslationTest)
#include "GuiTranslationTest.moc"
