// GNSS in metres: one geodetic origin per project (explicit or the first fix), every lat/lon stream
// with x, y, z (m) in that shared East-North-Up frame; fix quality, satellites and HDOP kept.
#include "TestFiles.h"
#include "core/geometry/Geodesy.h"
#include "core/geometry/LocalTangentPlane.h"
#include "core/io/Importer.h"

#include "tests/SharedData.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;

TEST(Geodesy, EnuAxesAndRoundTrip) {
    const LocalTangentPlane plane(0.0, 0.0, 0.0);
    // One millidegree north / east at the equator: 110.574 m / 111.319 m (WGS-84).
    EXPECT_NEAR(plane.toEnu(0.001, 0.0, 0.0).y(), 110.574, 1e-3);
    EXPECT_NEAR(plane.toEnu(0.0, 0.001, 0.0).x(), 111.319, 1e-3);
    EXPECT_NEAR(plane.toEnu(0.0, 0.0, 10.0).z(), 10.0, 1e-9);
    const LocalTangentPlane munich(48.1, 11.5, 520.0);
    const Eigen::Vector3d back = munich.toGeodetic(munich.toEnu(48.101, 11.502, 530.0));
    EXPECT_NEAR(back.x(), 48.101, 1e-9);
    EXPECT_NEAR(back.y(), 11.502, 1e-9);
    EXPECT_NEAR(back.z(), 530.0, 1e-3);
}

TEST(Geodesy, OriginOption) {
    EXPECT_EQ(*parseGeodeticOrigin("48.1, 11.5"), (GeodeticOrigin{48.1, 11.5, 0.0}));
    EXPECT_EQ(*parseGeodeticOrigin("-27.2,153.05,4"), (GeodeticOrigin{-27.2, 153.05, 4.0}));
    EXPECT_TRUE(parseGeodeticOrigin("48.1").message().contains("expected LAT,LON[,HEIGHT]"));
    EXPECT_TRUE(parseGeodeticOrigin("north,11").message().contains("'north' is not a number"));
    EXPECT_TRUE(parseGeodeticOrigin("91,11").message().contains("latitude must be in [-90, 90]"));
}

TEST(Geodesy, ProjectOriginIsSharedByEveryGnssStream) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("p.athlos"));
    ImportOptions options;
    options.kind = QStringLiteral("gnss");
    options.target = QStringLiteral("a");
    // Names in any case; fix quality, satellites and HDOP kept as columns.
    const QString a = test::writeFile(
        dir, "a.csv", "t,Latitude,Longitude,Altitude,fix,sats,HDOP\n0,0,0,0,4,12,0.7\n1,0.001,0,0,4,12,0.8\n");
    auto r = importFile(a, options);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_TRUE(applyImport(*project, *r, false).ok());
    EXPECT_EQ(projectOrigin(project->meta()), (GeodeticOrigin{0.0, 0.0, 0.0}));  // the first fix
    const Stream* s = project->stream("a/gnss");
    ASSERT_NE(s, nullptr);
    QStringList names;
    for (const Column& c : s->info().columns) names << c.name;
    EXPECT_EQ(names, (QStringList{"lat", "lon", "alt", "fix", "sats", "hdop", "x", "y", "z"}));
    const auto d = *s->data();
    EXPECT_NEAR(d->at(1, 7), 110.574, 1e-3);
    EXPECT_NEAR(d->at(0, 6), 0.0, 1e-9);
    EXPECT_EQ(d->at(0, 3), 4.0);

    // The second stream is in the same frame, not about its own first fix.
    options.target = QStringLiteral("b");
    const QString b = test::writeFile(dir, "b.csv", "t,lat,lon\n0,0,0.001\n");
    r = importFile(b, options);
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(applyImport(*project, *r, false).ok());
    EXPECT_NEAR((*project->stream("b/gnss")->data())->at(0, 2), 111.319, 1e-3);
    EXPECT_EQ(project->stream("b/gnss")->info().attributes.value("enu_origin").toObject().value("lat").toDouble(), 0.0);

    // An explicit origin that differs from the project's: refused, nothing changed.
    options.target = QStringLiteral("c");
    options.origin = GeodeticOrigin{1.0, 1.0, 0.0};
    r = importFile(b, options);
    ASSERT_TRUE(r.ok());
    const Status refused = applyImport(*project, *r, false);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains("geodetic origin is 0, 0, 0 m; it cannot change"))
        << qPrintable(refused.message());
    EXPECT_EQ(project->stream("c/gnss"), nullptr);
}

TEST(Geodesy, NmeaWalkInMetres) {
    // haicom-305N: stationary, then 5 m west, 10 m south and back (the log's description).
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("p.athlos"));
    ImportOptions options;
    options.target = QStringLiteral("walk");
    const QString log = QString::fromUtf8(ATHLOS_SHARED_DATA_DIR "/nmea/haicom-305N.log");
    ATHLOS_SKIP_WITHOUT_SHARED(log);
    auto r = importFile(log, options);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_TRUE(applyImport(*project, *r, false).ok());
    const Stream* s = project->stream("walk/gnss");
    ASSERT_NE(s, nullptr);
    const int x = s->info().columnIndex("x"), y = s->info().columnIndex("y");
    ASSERT_GE(x, 0);
    const auto d = *s->data();
    double minX = 0, maxX = 0, minY = 0, maxY = 0;
    for (size_t i = 0; i < d->rows(); ++i) {
        minX = std::min(minX, d->at(i, x)), maxX = std::max(maxX, d->at(i, x));
        minY = std::min(minY, d->at(i, y)), maxY = std::max(maxY, d->at(i, y));
    }
    EXPECT_EQ(d->at(0, x), 0.0);
    EXPECT_LT(maxX - minX, 100.0);  // metres, not degrees: a walk of a few metres with SiRF-II noise
    EXPECT_LT(maxY - minY, 100.0);
    EXPECT_GT(maxX - minX + maxY - minY, 2.0);
}
